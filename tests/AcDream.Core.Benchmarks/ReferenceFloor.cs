using System.Numerics;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// A cell's floors in double precision, brute force: each polygon's vertices moved to
/// landblock-local space with the normalised quaternion in double, fan-triangulated; a point is on a
/// triangle when its exact barycentric weights are all ≥ 0; Z is the exact barycentric blend.
/// </summary>
internal sealed class ReferenceFloor
{
    private readonly List<(double X, double Y, double Z)[]> _triangles = [];

    public ReferenceFloor(IEnumerable<Vector3[]> cellLocalFloors, Vector3 origin, Quaternion stored)
    {
        double qx = stored.X, qy = stored.Y, qz = stored.Z, qw = stored.W;
        double n = Math.Sqrt((qx * qx) + (qy * qy) + (qz * qz) + (qw * qw));
        qx /= n;
        qy /= n;
        qz /= n;
        qw /= n;
        MinX = MinY = double.MaxValue;
        MaxX = MaxY = double.MinValue;
        foreach (Vector3[] polygon in cellLocalFloors)
        {
            var v = new (double X, double Y, double Z)[polygon.Length];
            for (int i = 0; i < polygon.Length; i++)
            {
                // v' = v + 2w(q × v) + 2 q × (q × v), the rotation by a unit quaternion.
                double vx = polygon[i].X, vy = polygon[i].Y, vz = polygon[i].Z;
                double tx = 2 * ((qy * vz) - (qz * vy)), ty = 2 * ((qz * vx) - (qx * vz)), tz = 2 * ((qx * vy) - (qy * vx));
                v[i] = (
                    origin.X + vx + (qw * tx) + ((qy * tz) - (qz * ty)),
                    origin.Y + vy + (qw * ty) + ((qz * tx) - (qx * tz)),
                    origin.Z + vz + (qw * tz) + ((qx * ty) - (qy * tx)));
                MinX = Math.Min(MinX, v[i].X);
                MinY = Math.Min(MinY, v[i].Y);
                MaxX = Math.Max(MaxX, v[i].X);
                MaxY = Math.Max(MaxY, v[i].Y);
            }

            for (int i = 1; i + 1 < v.Length; i++)
            {
                _triangles.Add([v[0], v[i], v[i + 1]]);
            }
        }
    }

    public double MinX { get; }

    public double MinY { get; }

    public double MaxX { get; }

    public double MaxY { get; }

    /// <summary>
    /// Topmost floor Z under (x, y), or null. <paramref name="edgeDistance"/>: distance (m) from the
    /// point to the nearest triangle edge, for judging disagreements near edges.
    /// </summary>
    public double? TopZ(double x, double y, out double edgeDistance)
    {
        double? best = null;
        edgeDistance = double.MaxValue;
        foreach ((double X, double Y, double Z)[] t in _triangles)
        {
            var (a, b, c) = (t[0], t[1], t[2]);
            edgeDistance = Math.Min(edgeDistance, Math.Min(Segment(x, y, a, b), Math.Min(Segment(x, y, b, c), Segment(x, y, c, a))));
            double det = ((b.Y - c.Y) * (a.X - c.X)) + ((c.X - b.X) * (a.Y - c.Y));
            if (det == 0)
            {
                continue;
            }

            double wa = (((b.Y - c.Y) * (x - c.X)) + ((c.X - b.X) * (y - c.Y))) / det;
            double wb = (((c.Y - a.Y) * (x - c.X)) + ((a.X - c.X) * (y - c.Y))) / det;
            double wc = 1 - wa - wb;
            if (wa < 0 || wb < 0 || wc < 0)
            {
                continue;
            }

            double z = (wa * a.Z) + (wb * b.Z) + (wc * c.Z);
            best = best is double z0 ? Math.Max(z0, z) : z;
        }

        return best;
    }

    /// <summary>A random point on a random edge (or vertex) of a random fan triangle.</summary>
    public (double X, double Y) RandomEdgePoint(Random random)
    {
        (double X, double Y, double Z)[] t = _triangles[random.Next(_triangles.Count)];
        int e = random.Next(3);
        var (a, b) = (t[e], t[(e + 1) % 3]);
        double s = random.Next(10) == 0 ? 0 : random.NextDouble();
        return (a.X + (s * (b.X - a.X)), a.Y + (s * (b.Y - a.Y)));
    }

    /// <summary>Distance, seen from above, from (px, py) to the segment a–b.</summary>
    internal static double Segment(double px, double py, (double X, double Y, double Z) a, (double X, double Y, double Z) b)
    {
        double dx = b.X - a.X, dy = b.Y - a.Y;
        double l2 = (dx * dx) + (dy * dy);
        double s = l2 > 0 ? Math.Clamp((((px - a.X) * dx) + ((py - a.Y) * dy)) / l2, 0, 1) : 0;
        double ex = px - (a.X + (s * dx)), ey = py - (a.Y + (s * dy));
        return Math.Sqrt((ex * ex) + (ey * ey));
    }
}
