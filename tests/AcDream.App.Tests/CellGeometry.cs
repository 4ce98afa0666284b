using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.App.World;
using static AcDream.Testing.ReferenceBody;

namespace AcDream.App.Tests;

/// <summary>
/// The Holtburg cells' polygons placed in double precision (landblock-local, which is world in the scenes' frame), and
/// brute-force distances to them: a reference for the camera's and the pointer's answers, independent of the engine.
/// </summary>
internal static class CellGeometry
{
    /// <summary>Every cell's wall polygons (<see cref="WallsOf"/>: not floors, not a portal's cover; ceilings are in), with the cell's id.</summary>
    public static List<(uint CellId, Vec3[] Polygon)> Walls(HoltburgWorld world) =>
        [.. world.Cells.SelectMany(c => WallsOf(c.EnvCell, c.CellStruct).Select(w => (c.CellId, w)))];

    /// <summary>Every cell's portals to the outdoors (the drawing polygon each names), with the cell's id.</summary>
    public static List<(uint CellId, Vec3[] Polygon)> OutdoorPortals(HoltburgWorld world) =>
        [.. world.Cells.SelectMany(c => c.EnvCell.CellPortals.Where(p => p.OtherCellId == 0xFFFF)
            .Select(p => (c.CellId, Placed(c, c.CellStruct.Polygons[p.PolygonId].VertexIds))))];

    /// <summary>The polygon's vertices, cell-local, placed by the cell's frame.</summary>
    private static Vec3[] Placed(CellFixtureReader.FixtureCell cell, IEnumerable<short> vertexIds) =>
        [.. vertexIds.Select(id => Place(cell.EnvCell.Position, cell.CellStruct.VertexArray.Vertices[(ushort)id].Origin))];

    public static Vec3 V(Vector3 v) => new(v.X, v.Y, v.Z);

    /// <summary>The distance from <paramref name="p"/> to the polygon (a flat convex or concave polygon): to its face if the point projects inside it, else to its nearest edge.</summary>
    public static double Distance(Vec3 p, Vec3[] polygon)
    {
        (Vec3 n, double d) = Plane(polygon);
        double above = Dot(n, p) + d;
        Vec3 onPlane = Sub(p, Scale(n, above));
        if (Inside(onPlane, polygon, n))
        {
            return Math.Abs(above);
        }

        double best = double.PositiveInfinity;
        for (int i = 0; i < polygon.Length; i++)
        {
            best = Math.Min(best, SegmentDistance(p, polygon[i], polygon[(i + 1) % polygon.Length]));
        }

        return best;
    }

    /// <summary>Whether the segment from <paramref name="a"/> to <paramref name="b"/> passes through the polygon (touching counts).</summary>
    public static bool Crosses(Vec3 a, Vec3 b, Vec3[] polygon)
    {
        (Vec3 n, double d) = Plane(polygon);
        double da = Dot(n, a) + d, db = Dot(n, b) + d;
        if ((da > 0 && db > 0) || (da < 0 && db < 0) || da == db)
        {
            return false;
        }

        double t = da / (da - db);
        return Inside(Add(a, Scale(Sub(b, a), t)), polygon, n);
    }

    /// <summary>The unit normal (Newell) and offset of the polygon's plane: n·x + d = 0.</summary>
    private static (Vec3 Normal, double D) Plane(Vec3[] v)
    {
        Vec3 n = Newell(v);
        n = Scale(n, 1 / n.Length);
        var c = new Vec3(v.Average(p => p.X), v.Average(p => p.Y), v.Average(p => p.Z));
        return (n, -Dot(n, c));
    }

    /// <summary>Whether a point on the polygon's plane is inside it: crossings of a ray in the plane dropped to its dominant axis.</summary>
    private static bool Inside(Vec3 p, Vec3[] polygon, Vec3 n)
    {
        Func<Vec3, (double, double)> flat = Math.Abs(n.Z) >= Math.Abs(n.X) && Math.Abs(n.Z) >= Math.Abs(n.Y) ? v => (v.X, v.Y)
            : Math.Abs(n.X) >= Math.Abs(n.Y) ? v => (v.Y, v.Z) : v => (v.X, v.Z);
        (double px, double py) = flat(p);
        bool inside = false;
        for (int i = 0, j = polygon.Length - 1; i < polygon.Length; j = i++)
        {
            (double xi, double yi) = flat(polygon[i]);
            (double xj, double yj) = flat(polygon[j]);
            if ((yi > py) != (yj > py) && px < ((xj - xi) * (py - yi) / (yj - yi)) + xi)
            {
                inside = !inside;
            }
        }

        return inside;
    }

    private static double SegmentDistance(Vec3 p, Vec3 a, Vec3 b)
    {
        Vec3 ab = Sub(b, a);
        double t = Math.Clamp(Dot(Sub(p, a), ab) / Dot(ab, ab), 0, 1);
        return Sub(p, Add(a, Scale(ab, t))).Length;
    }

    private static double Dot(Vec3 a, Vec3 b) => (a.X * b.X) + (a.Y * b.Y) + (a.Z * b.Z);

    private static Vec3 Add(Vec3 a, Vec3 b) => new(a.X + b.X, a.Y + b.Y, a.Z + b.Z);

    private static Vec3 Sub(Vec3 a, Vec3 b) => new(a.X - b.X, a.Y - b.Y, a.Z - b.Z);

    private static Vec3 Scale(Vec3 a, double s) => new(a.X * s, a.Y * s, a.Z * s);
}
