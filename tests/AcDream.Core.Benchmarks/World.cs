using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.Core.Dat;
using AcDream.Core.Physics;

namespace AcDream.Core.Benchmarks;

/// <summary>Seeded builders for the benchmark and accuracy worlds. Landblock-local metres throughout.</summary>
internal static class World
{
    /// <summary>Holtburg, the centre landblock of every benchmark world.</summary>
    public const uint Holtburg = 0xA9B4FFFFu;

    /// <summary>Floor height of the Holtburg cottages (metres); the indoor world's flat terrain sits there.</summary>
    public const float HoltburgGroundZ = 94f;

    public const float PlayerStepUp = 0.5f;

    /// <summary>A non-linear table like the game's: fine steps low, coarse steps high (metres).</summary>
    public static float[] NonLinearTable()
    {
        var table = new float[256];
        for (int i = 0; i < 256; i++)
        {
            table[i] = (0.5f * i) + (0.02f * i * i);
        }

        return table;
    }

    /// <summary>Every index gives <paramref name="z"/> metres.</summary>
    public static float[] ConstantTable(float z)
    {
        var table = new float[256];
        Array.Fill(table, z);
        return table;
    }

    /// <summary>Rolling land: each vertex is <paramref name="baseIndex"/> ± <paramref name="spread"/> table indices.</summary>
    public static byte[] RollingHeights(Random random, int baseIndex, int spread)
    {
        var heights = new byte[81];
        for (int i = 0; i < heights.Length; i++)
        {
            heights[i] = (byte)Math.Clamp(baseIndex + random.Next(-spread, spread + 1), 0, 255);
        }

        return heights;
    }

    public static uint LandblockId(int x, int y) => ((uint)x << 24) | ((uint)y << 16) | 0xFFFFu;

    /// <summary>The 1 or 9 landblock ids centred on Holtburg (the centre first).</summary>
    public static List<uint> Landblocks(int count)
    {
        int cx = (int)(Holtburg >> 24), cy = (int)((Holtburg >> 16) & 0xFF);
        var ids = new List<uint> { Holtburg };
        if (count == 9)
        {
            for (int dx = -1; dx <= 1; dx++)
            {
                for (int dy = -1; dy <= 1; dy++)
                {
                    if (dx != 0 || dy != 0)
                    {
                        ids.Add(LandblockId(cx + dx, cy + dy));
                    }
                }
            }
        }

        return ids;
    }

    /// <summary>
    /// <paramref name="count"/> one-room buildings (6 m square floor, four walls, a doorway to the
    /// outdoors in the south wall) standing on the terrain, in the east half of the landblock
    /// (outdoor cells x ≥ 4), two per outdoor cell at most: away from a mover kept in the west half.
    /// </summary>
    public static List<CellSurface> Buildings(uint landblockId, TerrainSurface terrain, int count)
    {
        var cells = new List<CellSurface>(count);
        for (int i = 0; i < count; i++)
        {
            int outdoor = i % 32;
            float ox = 96f + ((outdoor / 8) * 24f) + (i < 32 ? 3f : 14f);
            float oy = ((outdoor % 8) * 24f) + (i < 32 ? 3f : 14f);
            float oz = terrain.SampleZ(ox + 3f, oy + 3f);
            uint id = (landblockId & 0xFFFF0000u) | (uint)(0x0100 + i);
            cells.Add(Room(id, new Vector3(ox, oy, oz), Quaternion.Identity, 6f).Build());
        }

        return cells;
    }

    /// <summary>
    /// Open ground: 9 landblocks of rolling terrain (index 60 ± 6 of the non-linear table) with 64 <see cref="Buildings"/> in
    /// each, centred on Holtburg; returns the centre's terrain. Movers in its west half meet no wall.
    /// </summary>
    public static PhysicsEngine OpenGround(Random random, out TerrainSurface centre)
    {
        float[] table = NonLinearTable();
        var engine = new PhysicsEngine(Holtburg);
        centre = null!;
        foreach (uint id in Landblocks(9))
        {
            var terrain = new TerrainSurface(RollingHeights(random, 60, 6), table, id);
            engine.AddLandblock(id, terrain, Buildings(id, terrain, 64));
            centre ??= terrain;
        }

        return engine;
    }

    /// <summary>A one-room cell: floor [0, size]², walls 3 m high, a 1 m doorway to the outdoors centred in the south wall.</summary>
    public static CellBuilder Room(uint cellId, Vector3 origin, Quaternion orientation, float size)
    {
        var b = new CellBuilder(cellId, origin, orientation);
        b.Floor(0, 0, size, size, 0);
        b.Physics(Wall(0, 0, size, 0, 0, 3));
        b.Physics(Wall(size, 0, size, size, 0, 3));
        b.Physics(Wall(size, size, 0, size, 0, 3));
        b.Physics(Wall(0, size, 0, 0, 0, 3));
        float mid = size / 2;
        var inside = new Vector3(mid, mid, 1);
        b.Portal(0xFFFF, inside, new(mid - 0.5f, 0, 0), new(mid + 0.5f, 0, 0), new(mid + 0.5f, 0, 2.5f), new(mid - 0.5f, 0, 2.5f));
        return b;
    }

    public static Vector3[] Square(float minX, float minY, float maxX, float maxY, float z) =>
        CellBuilder.Square(minX, minY, maxX, maxY, z);

    public static Vector3[] Wall(float x0, float y0, float x1, float y1, float z0, float z1) =>
        [new(x0, y0, z0), new(x1, y1, z0), new(x1, y1, z1), new(x0, y0, z1)];

    /// <summary>
    /// The indoor world: the cells on flat terrain at <see cref="HoltburgGroundZ"/> in Holtburg, and the
    /// empty landblock south of it (some cells reach across the seam).
    /// </summary>
    public static PhysicsEngine IndoorEngine(List<CellSurface> surfaces)
    {
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, new TerrainSurface(new byte[81], ConstantTable(HoltburgGroundZ), Holtburg), surfaces);
        engine.AddLandblock(0xA9B3FFFFu, new TerrainSurface(new byte[81], ConstantTable(HoltburgGroundZ), 0xA9B3FFFFu), []);
        return engine;
    }

    /// <summary>
    /// A random point on a floor of a random real cell where the player's body
    /// (<see cref="MoverBody.Player"/>) stands clear of every wall (<see cref="Clearance"/> at least its
    /// radius between the step height and its top): a body never starts a frame inside a wall.
    /// </summary>
    public static (Vector3 Position, uint CellId) IndoorStart(
        Random random, List<CellFixtureReader.FixtureCell> fixtures, List<CellSurface> surfaces, List<WallFace> walls, ref int redrawn)
    {
        MoverBody body = MoverBody.Player;
        while (true)
        {
            int c = random.Next(fixtures.Count);
            (Vector2 min, Vector2 max) = Bounds(fixtures[c]);
            float x = min.X + (random.NextSingle() * (max.X - min.X)), y = min.Y + (random.NextSingle() * (max.Y - min.Y));
            if (surfaces[c].SampleFloorZ(x, y) is not float z)
            {
                continue; // no floor there (a wall's footprint, a shaft): draw again
            }

            if (Clearance(walls, new Vector2(x, y), z + PlayerStepUp, z + body.Height) < body.Radius)
            {
                redrawn++;
                continue; // the body would start inside a wall
            }

            return (new Vector3(x, y, z), surfaces[c].CellId);
        }
    }

    /// <summary>The 22 real Holtburg cells, in id order.</summary>
    public static List<CellFixtureReader.FixtureCell> HoltburgFixtures()
    {
        string folder = Path.Combine(AppContext.BaseDirectory, "Fixtures", "holtburg-cells");
        var cells = new List<CellFixtureReader.FixtureCell>();
        foreach (string path in Directory.GetFiles(folder, "*.json"))
        {
            cells.Add(CellFixtureReader.Read(File.ReadAllText(path), path));
        }

        cells.Sort((a, b) => a.CellId.CompareTo(b.CellId));
        return cells;
    }

    public static List<CellSurface> Surfaces(IEnumerable<CellFixtureReader.FixtureCell> fixtures)
    {
        var list = new List<CellSurface>();
        foreach (CellFixtureReader.FixtureCell f in fixtures)
        {
            list.Add(new CellSurface(f.CellId, f.EnvCell, f.CellStruct));
        }

        return list;
    }

    /// <summary>Landblock-local XY bounds of a fixture's physics polygons.</summary>
    public static (Vector2 Min, Vector2 Max) Bounds(CellFixtureReader.FixtureCell cell)
    {
        Quaternion q = Quaternion.Normalize(cell.EnvCell.Position.Orientation);
        Vector2 min = new(float.MaxValue), max = new(float.MinValue);
        foreach (Polygon polygon in cell.CellStruct.PhysicsPolygons.Values)
        {
            foreach (short id in polygon.VertexIds)
            {
                Vector3 v = cell.EnvCell.Position.Origin + Vector3.Transform(cell.CellStruct.VertexArray.Vertices[(ushort)id].Origin, q);
                min = Vector2.Min(min, new Vector2(v.X, v.Y));
                max = Vector2.Max(max, new Vector2(v.X, v.Y));
            }
        }

        return (min, max);
    }

    /// <summary>
    /// One non-floor physics polygon of a real cell (a wall, a ceiling, a steep face), landblock-local,
    /// with its unit winding normal and its height range: what the body may meet. Computed here from
    /// the fixtures, independently of the engine, to place movers and check where they are.
    /// </summary>
    public sealed record WallFace(uint CellId, Vector2[] Outline, Vector3 Normal, float ZMin, float ZMax)
    {
        /// <summary>Vertical (a wall proper, not a ceiling or a slope).</summary>
        public bool IsVertical => MathF.Abs(Normal.Z) < 0.05f;
    }

    /// <summary>Every non-floor physics polygon (unit normal Z below <see cref="PhysicsConstants.FloorZ"/>) of the fixtures.</summary>
    public static List<WallFace> Walls(IEnumerable<CellFixtureReader.FixtureCell> fixtures)
    {
        var walls = new List<WallFace>();
        foreach (CellFixtureReader.FixtureCell cell in fixtures)
        {
            Quaternion q = Quaternion.Normalize(cell.EnvCell.Position.Orientation);
            foreach (Polygon polygon in cell.CellStruct.PhysicsPolygons.Values)
            {
                var v = new Vector3[polygon.VertexIds.Count];
                for (int i = 0; i < v.Length; i++)
                {
                    v[i] = cell.EnvCell.Position.Origin + Vector3.Transform(cell.CellStruct.VertexArray.Vertices[(ushort)polygon.VertexIds[i]].Origin, q);
                }

                Vector3 normal = Vector3.Zero; // Newell's method
                for (int i = 0; i < v.Length; i++)
                {
                    Vector3 a = v[i], b = v[(i + 1) % v.Length];
                    normal += new Vector3((a.Y - b.Y) * (a.Z + b.Z), (a.Z - b.Z) * (a.X + b.X), (a.X - b.X) * (a.Y + b.Y));
                }

                if (normal.Length() < 1e-6f || (normal = Vector3.Normalize(normal)).Z >= PhysicsConstants.FloorZ)
                {
                    continue;
                }

                walls.Add(new WallFace(
                    cell.CellId,
                    [.. v.Select(p => new Vector2(p.X, p.Y))],
                    normal,
                    v.Min(p => p.Z),
                    v.Max(p => p.Z)));
            }
        }

        return walls;
    }

    /// <summary>
    /// The horizontal distance from <paramref name="p"/> to the nearest of <paramref name="walls"/>
    /// whose height range overlaps (<paramref name="zLow"/>, <paramref name="zHigh"/>), each taken whole
    /// (conservative: a polygon reaching into the band counts with all of its outline); 0 inside one's outline.
    /// </summary>
    public static float Clearance(List<WallFace> walls, Vector2 p, float zLow, float zHigh)
    {
        float best = float.MaxValue;
        foreach (WallFace w in walls)
        {
            if (w.ZMax <= zLow || w.ZMin >= zHigh)
            {
                continue;
            }

            bool inside = false;
            Vector2[] o = w.Outline;
            for (int i = 0, j = o.Length - 1; i < o.Length; j = i++)
            {
                best = MathF.Min(best, SegmentDistance(p, o[j], o[i]));
                if ((o[i].Y > p.Y) != (o[j].Y > p.Y) && p.X < o[j].X + ((o[i].X - o[j].X) * (p.Y - o[j].Y) / (o[i].Y - o[j].Y)))
                {
                    inside = !inside;
                }
            }

            if (inside)
            {
                return 0f;
            }
        }

        return best;
    }

    private static float SegmentDistance(Vector2 p, Vector2 a, Vector2 b)
    {
        Vector2 ab = b - a;
        float t = ab.LengthSquared() > 0f ? Math.Clamp(Vector2.Dot(p - a, ab) / ab.LengthSquared(), 0f, 1f) : 0f;
        return Vector2.Distance(p, a + (t * ab));
    }

    /// <summary>A random horizontal move of length in [min, max] metres.</summary>
    public static Vector3 RandomDelta(Random random, float min, float max)
    {
        double angle = random.NextDouble() * 2 * Math.PI;
        float length = min + ((max - min) * random.NextSingle());
        return new Vector3(length * (float)Math.Cos(angle), length * (float)Math.Sin(angle), 0f);
    }

    /// <summary>Outdoor cell number (0x0001..0x0040) of a landblock-local point.</summary>
    public static uint OutdoorCell(float x, float y)
    {
        int cx = Math.Clamp((int)(x / 24f), 0, 7), cy = Math.Clamp((int)(y / 24f), 0, 7);
        return (uint)((cx * 8) + cy + 1);
    }
}
