using System.Numerics;
using System.Text;
using System.Xml.Linq;
using AcDream.App.World;
using AcDream.Core.Physics;

namespace AcDream.App.Scenes;

// The map's terrain contours.
internal static partial class WalkSvg
{
    /// <summary>
    /// Marching squares over the terrain, sampled on a grid of about 1.5 px; one path per 2 m level.
    /// The map is padded past the route, so it can reach past the world's edge: there the edge
    /// landblock's terrain is sampled, clamped to its edge (flat outwards).
    /// </summary>
    private static void AddContours(XElement parent, HoltburgWorld world, PhysicsEngine frame, MapExtent extent, Func<float, float, Vector2> place)
    {
        (float minX, float maxX, float minY, float maxY) = extent;
        var terrains = new Dictionary<uint, TerrainSurface>();
        float Z(float x, float y)
        {
            var at = new Vector3(x, y, 0f);
            uint id = frame.LandblockAt(at);
            if (!terrains.TryGetValue(id, out TerrainSurface? terrain))
            {
                terrains[id] = terrain = world.Terrain(id);
            }

            Vector3 local = frame.ToLandblockLocal(id, at);
            return terrain.SampleZ(local.X, local.Y);
        }

        int nx = 240, ny = Math.Max(2, (int)(nx * (maxY - minY) / (maxX - minX)));
        float dx = (maxX - minX) / nx, dy = (maxY - minY) / ny;
        var grid = new float[nx + 1, ny + 1];
        var all = new List<float>();
        for (int i = 0; i <= nx; i++)
        {
            for (int j = 0; j <= ny; j++)
            {
                grid[i, j] = Z(minX + (i * dx), minY + (j * dy));
                all.Add(grid[i, j]);
            }
        }

        // Levels between the 2nd and 98th percentile: a needle does not drown the hills in rings.
        all.Sort();
        float low = all[all.Count * 2 / 100], high = all[Math.Min(all.Count - 1, all.Count * 98 / 100)];
        var heights = new HeightGrid(grid, minX, minY, dx, dy);
        var contours = new XElement(Svg + "g", new XAttribute("id", "contours"), new XAttribute("fill", "none"), new XAttribute("stroke", "#b59b6a"));
        for (float level = MathF.Ceiling(low / ContourInterval) * ContourInterval; level <= high; level += ContourInterval)
        {
            var path = new StringBuilder();
            for (int i = 0; i < nx; i++)
            {
                for (int j = 0; j < ny; j++)
                {
                    AddCellSegments(path, level, i, j, heights, place);
                }
            }

            if (path.Length > 0)
            {
                bool major = MathF.Abs(level % 10f) < 0.01f;
                contours.Add(new XElement(Svg + "path", new XAttribute("d", path.ToString()), Attr("stroke-width", major ? 1.0f : 0.5f), new XElement(Svg + "title", Invariant($"{level} m"))));
            }
        }

        parent.Add(contours);
        float peak = all[^1];
        if (peak > high + ContourInterval)
        {
            for (int i = 0; i <= nx; i++)
            {
                for (int j = 0; j <= ny; j++)
                {
                    if (grid[i, j] == peak)
                    {
                        Vector2 p = place(minX + (i * dx), minY + (j * dy));
                        parent.Add(Label(p.X - 4, p.Y + 4, Invariant($"▲ {peak:0} m"), 11));
                        return;
                    }
                }
            }
        }
    }

    private static void AddCellSegments(StringBuilder path, float level, int i, int j, HeightGrid heights, Func<float, float, Vector2> place)
    {
        (float[,] grid, float minX, float minY, float dx, float dy) = heights;
        float z00 = grid[i, j], z10 = grid[i + 1, j], z01 = grid[i, j + 1], z11 = grid[i + 1, j + 1];
        Span<Vector2> crossings = stackalloc Vector2[4];
        int n = 0;
        float x0 = minX + (i * dx), y0 = minY + (j * dy);
        void Edge(float za, float zb, Vector2 a, Vector2 b, Span<Vector2> into)
        {
            if ((za < level) != (zb < level))
            {
                float t = (level - za) / (zb - za);
                into[n++] = Vector2.Lerp(a, b, t);
            }
        }

        Edge(z00, z10, new(x0, y0), new(x0 + dx, y0), crossings);
        Edge(z10, z11, new(x0 + dx, y0), new(x0 + dx, y0 + dy), crossings);
        Edge(z11, z01, new(x0 + dx, y0 + dy), new(x0, y0 + dy), crossings);
        Edge(z01, z00, new(x0, y0 + dy), new(x0, y0), crossings);
        for (int k = 0; k + 1 < n; k += 2)
        {
            Vector2 a = place(crossings[k].X, crossings[k].Y), b = place(crossings[k + 1].X, crossings[k + 1].Y);
            path.Append(Invariant($"M{a.X:0.#},{a.Y:0.#}L{b.X:0.#},{b.Y:0.#}"));
        }
    }

    /// <summary>The map's extent in world metres: the route, padded.</summary>
    private readonly record struct MapExtent(float MinX, float MaxX, float MinY, float MaxY);

    /// <summary>The terrain sampled for the contours: <c>Grid[i, j]</c> is the height at world (<c>MinX + i * Dx</c>, <c>MinY + j * Dy</c>).</summary>
    private readonly record struct HeightGrid(float[,] Grid, float MinX, float MinY, float Dx, float Dy);
}
