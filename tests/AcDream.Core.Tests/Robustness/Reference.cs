using System.Numerics;
using AcDream.Core.Dat;

namespace AcDream.Core.Tests.Robustness;

/// <summary>
/// Slow, obviously-correct references in double precision, written from the facts and the
/// documented rules, not from the engine's code: the game's two-triangle terrain and the
/// brute-force floor of a cell.
/// </summary>
internal static class Reference
{
    public const double EdgeTolerance = 0.0002;
    public const double FloorZ = 0.66417414618662751;

    /// <summary>
    /// The game's terrain at landblock-local (x, y): the plane of whichever of the cell's two
    /// triangles contains the point, the diagonal chosen by the split hash of the global cell.
    /// </summary>
    public static double TerrainZ(byte[] heights, float[] table, int landblockX, int landblockY, double x, double y)
    {
        x = Math.Clamp(x, 0.0, 192.0);
        y = Math.Clamp(y, 0.0, 192.0);
        int cx = Math.Min((int)Math.Floor(x / 24.0), 7);
        int cy = Math.Min((int)Math.Floor(y / 24.0), 7);
        D3 Corner(int i, int j) => new(24.0 * (cx + i), 24.0 * (cy + j), table[heights[((cx + i) * 9) + cy + j]]);
        D3 sw = Corner(0, 0), se = Corner(1, 0), nw = Corner(0, 1), ne = Corner(1, 1);

        ulong gx = (ulong)((landblockX * 8) + cx), gy = (ulong)((landblockY * 8) + cy);
        ulong split = ((gx * gy * 0x0CCAC033UL) - (gx * 0x421BE3BDUL) + (gy * 0x6C1AC587UL) - 0x519B8F25UL) & 0xFFFF_FFFFUL;
        (D3, D3, D3)[] triangles = (split & 0x8000_0000UL) != 0
            ? [(sw, se, ne), (sw, ne, nw)]
            : [(sw, se, nw), (ne, nw, se)];

        foreach ((D3 a, D3 b, D3 c) in triangles)
        {
            if (MinEdgeDistance(a, b, c, x, y) >= -1e-9)
            {
                return PlaneZ(a, b, c, x, y);
            }
        }

        throw new InvalidOperationException($"no triangle of cell ({cx}, {cy}) contains ({x}, {y})");
    }

    /// <summary>Largest |gradient| (m/m) of the terrain: the steepest triangle's slope bound.</summary>
    public static double MaxGradient(byte[] heights, float[] table)
    {
        double max = 0;
        for (int x = 0; x < 9; x++)
        {
            for (int y = 0; y < 9; y++)
            {
                double h = table[heights[(x * 9) + y]];
                if (x < 8)
                {
                    max = Math.Max(max, Math.Abs(table[heights[((x + 1) * 9) + y]] - h));
                }

                if (y < 8)
                {
                    max = Math.Max(max, Math.Abs(table[heights[(x * 9) + y + 1]] - h));
                }
            }
        }

        return 2 * max / 24.0; // a triangle's gradient is at most the sum of its two edge slopes
    }

    /// <summary>One fan triangle of a floor polygon, landblock-local, in double.</summary>
    public readonly record struct Triangle(D3 A, D3 B, D3 C, ushort Polygon);

    /// <summary>
    /// The floor triangles of a cell by the documented rules: vertices placed by the normalised
    /// orientation, a polygon is a floor when its area-vector normal has Z ≥ FloorZ, fan-triangulated
    /// from its first vertex, triangles with a twice-area (seen from above) below 1e-8 m² or facing
    /// down dropped, slivers thinner than the edge tolerance (0.2 mm) dropped.
    /// </summary>
    public static List<Triangle> FloorTriangles(EnvCell envCell, CellStruct cellStruct)
    {
        Quaternion q = envCell.Position.Orientation;
        double qx = q.X, qy = q.Y, qz = q.Z, qw = q.W;
        double n = Math.Sqrt((qx * qx) + (qy * qy) + (qz * qz) + (qw * qw));
        (qx, qy, qz, qw) = (qx / n, qy / n, qz / n, qw / n);
        Vector3 o = envCell.Position.Origin;

        D3 Place(Vector3 v)
        {
            // p = q v q*, expanded as v + 2w (u × v) + 2 u × (u × v) with u = (qx, qy, qz).
            double tx = 2 * ((qy * v.Z) - (qz * v.Y)), ty = 2 * ((qz * v.X) - (qx * v.Z)), tz = 2 * ((qx * v.Y) - (qy * v.X));
            return new D3(
                o.X + v.X + (qw * tx) + ((qy * tz) - (qz * ty)),
                o.Y + v.Y + (qw * ty) + ((qz * tx) - (qx * tz)),
                o.Z + v.Z + (qw * tz) + ((qx * ty) - (qy * tx)));
        }

        var result = new List<Triangle>();
        foreach ((ushort key, Polygon polygon) in cellStruct.PhysicsPolygons)
        {
            D3[] v = polygon.VertexIds.Select(id => Place(cellStruct.VertexArray.Vertices[(ushort)id].Origin)).ToArray();

            // Area vector: half the sum of fan cross products (equal to Newell's normal).
            D3 area = default;
            for (int i = 1; i + 1 < v.Length; i++)
            {
                area += Cross(v[i] - v[0], v[i + 1] - v[0]);
            }

            double length = area.Length;
            if (!(length > 1e-8) || area.Z / length < FloorZ)
            {
                continue;
            }

            for (int i = 1; i + 1 < v.Length; i++)
            {
                double doubleArea = ((v[i].X - v[0].X) * (v[i + 1].Y - v[0].Y)) - ((v[i].Y - v[0].Y) * (v[i + 1].X - v[0].X));
                double longest = Math.Max(Distance2(v[0], v[i]), Math.Max(Distance2(v[i], v[i + 1]), Distance2(v[i + 1], v[0])));
                if (doubleArea >= 1e-8 && doubleArea / longest >= EdgeTolerance)
                {
                    result.Add(new Triangle(v[0], v[i], v[i + 1], key));
                }
            }
        }

        return result;
    }

    /// <summary>
    /// Brute-force floor query: the Z of each triangle containing (x, y) within the edge tolerance;
    /// whether any triangle is too close to that tolerance boundary for float and double to agree
    /// (<paramref name="margin"/> metres); and whether the point is within the margin of a containing
    /// triangle's edge, where the clamped edge rule and the plane differ by up to slope × tolerance.
    /// </summary>
    public static (List<double> Zs, bool Ambiguous, bool NearEdge) FloorZs(List<Triangle> triangles, double x, double y, double margin)
    {
        var zs = new List<double>();
        bool ambiguous = false, nearEdge = false;
        foreach (Triangle t in triangles)
        {
            double d = MinEdgeDistance(t.A, t.B, t.C, x, y);
            if (Math.Abs(d + EdgeTolerance) < margin)
            {
                ambiguous = true;
            }

            if (d >= -EdgeTolerance)
            {
                nearEdge |= d < margin;
                zs.Add(PlaneZClamped(t.A, t.B, t.C, x, y));
            }
        }

        return (zs, ambiguous, nearEdge);
    }

    /// <summary>Signed distance (metres, positive inside) from (x, y) to the nearest edge line of a counter-clockwise triangle.</summary>
    public static double MinEdgeDistance(D3 a, D3 b, D3 c, double x, double y)
    {
        static double Side(D3 p, D3 q, double x, double y)
        {
            double ex = q.X - p.X, ey = q.Y - p.Y;
            return ((ex * (y - p.Y)) - (ey * (x - p.X))) / Math.Sqrt((ex * ex) + (ey * ey));
        }

        return Math.Min(Side(a, b, x, y), Math.Min(Side(b, c, x, y), Side(c, a, x, y)));
    }

    /// <summary>Z of the plane through a, b, c at (x, y).</summary>
    public static double PlaneZ(D3 a, D3 b, D3 c, double x, double y)
    {
        D3 normal = Cross(b - a, c - a);
        return a.Z - (((normal.X * (x - a.X)) + (normal.Y * (y - a.Y))) / normal.Z);
    }

    /// <summary>The plane's Z, clamped to the triangle's Z range (the documented edge rule).</summary>
    public static double PlaneZClamped(D3 a, D3 b, D3 c, double x, double y) =>
        Math.Clamp(PlaneZ(a, b, c, x, y), Math.Min(a.Z, Math.Min(b.Z, c.Z)), Math.Max(a.Z, Math.Max(b.Z, c.Z)));

    /// <summary>Distance seen from above.</summary>
    public static double Distance2(D3 u, D3 v) => Math.Sqrt(((u.X - v.X) * (u.X - v.X)) + ((u.Y - v.Y) * (u.Y - v.Y)));

    public static D3 Cross(D3 u, D3 v) => new((u.Y * v.Z) - (u.Z * v.Y), (u.Z * v.X) - (u.X * v.Z), (u.X * v.Y) - (u.Y * v.X));

    /// <summary>A double-precision 3-vector.</summary>
    public readonly record struct D3(double X, double Y, double Z)
    {
        public double Length => Math.Sqrt((X * X) + (Y * Y) + (Z * Z));

        public static D3 operator +(D3 a, D3 b) => new(a.X + b.X, a.Y + b.Y, a.Z + b.Z);

        public static D3 operator -(D3 a, D3 b) => new(a.X - b.X, a.Y - b.Y, a.Z - b.Z);
    }
}
