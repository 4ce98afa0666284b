using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// A placed GfxObj's floors in double precision, from its definition alone: every physics polygon's
/// vertices moved to landblock-local space with the normalised quaternion in double, its Newell normal
/// in double; a polygon whose unit normal's Z is at least <see cref="PhysicsConstants.FloorZ"/> is a
/// floor, and its Z at (x, y) is its plane's, the plane through its vertices' mean. A point is on a floor
/// when it is inside the polygon's outline seen from above (inside one of its fan triangles, exactly).
/// </summary>
internal sealed class ReferenceObjectFloor
{
    private readonly List<Floor> _floors = [];

    public ReferenceObjectFloor(GfxObj gfxObj, Frame frame)
    {
        Quaternion s = frame.Orientation;
        double qx = s.X, qy = s.Y, qz = s.Z, qw = s.W;
        double n = Math.Sqrt((qx * qx) + (qy * qy) + (qz * qz) + (qw * qw));
        (qx, qy, qz, qw) = (qx / n, qy / n, qz / n, qw / n);
        foreach (ushort key in gfxObj.PhysicsPolygons.Keys.Order())
        {
            List<short> ids = gfxObj.PhysicsPolygons[key].VertexIds;
            var v = new (double X, double Y, double Z)[ids.Count];
            for (int i = 0; i < v.Length; i++)
            {
                // v' = v + 2w(q × v) + 2 q × (q × v), the rotation by a unit quaternion.
                Vector3 p = gfxObj.VertexArray.Vertices[(ushort)ids[i]].Origin;
                double vx = p.X, vy = p.Y, vz = p.Z;
                double tx = 2 * ((qy * vz) - (qz * vy)), ty = 2 * ((qz * vx) - (qx * vz)), tz = 2 * ((qx * vy) - (qy * vx));
                v[i] = (
                    frame.Origin.X + vx + (qw * tx) + ((qy * tz) - (qz * ty)),
                    frame.Origin.Y + vy + (qw * ty) + ((qz * tx) - (qx * tz)),
                    frame.Origin.Z + vz + (qw * tz) + ((qx * ty) - (qy * tx)));
            }

            double nx = 0, ny = 0, nz = 0, cx = 0, cy = 0, cz = 0;
            for (int i = 0; i < v.Length; i++)
            {
                var (a, b) = (v[i], v[(i + 1) % v.Length]);
                nx += (a.Y - b.Y) * (a.Z + b.Z);
                ny += (a.Z - b.Z) * (a.X + b.X);
                nz += (a.X - b.X) * (a.Y + b.Y);
                (cx, cy, cz) = (cx + a.X, cy + a.Y, cz + a.Z);
            }

            double length = Math.Sqrt((nx * nx) + (ny * ny) + (nz * nz));
            if (length == 0 || nz / length < PhysicsConstants.FloorZ)
            {
                continue;
            }

            _floors.Add(new Floor(v, (nx, ny, nz), (cx / v.Length, cy / v.Length, cz / v.Length)));
        }

        if (_floors.Count == 0)
        {
            throw new ArgumentException($"object 0x{gfxObj.Id:X8} has no floor.", nameof(gfxObj));
        }
    }

    /// <summary>A random point (double) of a random floor polygon: a random fan triangle, uniform barycentric weights; and that polygon.</summary>
    public (double X, double Y, int Floor) RandomPoint(Random random)
    {
        int f = random.Next(_floors.Count);
        (double X, double Y, double Z)[] v = _floors[f].Vertices;
        int t = 1 + random.Next(v.Length - 2);
        double u = random.NextDouble(), w = random.NextDouble();
        if (u + w > 1)
        {
            (u, w) = (1 - u, 1 - w);
        }

        var (a, b, c) = (v[0], v[t], v[t + 1]);
        return (a.X + (u * (b.X - a.X)) + (w * (c.X - a.X)), a.Y + (u * (b.Y - a.Y)) + (w * (c.Y - a.Y)), f);
    }

    /// <summary>Floor <paramref name="floor"/>'s plane Z at (x, y).</summary>
    public double PlaneZ(int floor, double x, double y) => _floors[floor].PlaneZ(x, y);

    /// <summary>The highest floor Z under (x, y) no higher than <paramref name="ceiling"/>, or null.</summary>
    public double? TopZ(double x, double y, double ceiling)
    {
        double? best = null;
        foreach (Floor f in _floors)
        {
            if (f.Contains(x, y) && f.PlaneZ(x, y) is double z && z <= ceiling && !(best >= z))
            {
                best = z;
            }
        }

        return best;
    }

    /// <summary>
    /// The floor a mover with its feet at <paramref name="feet"/> and step <paramref name="step"/> comes to rest on
    /// at (x, y), as the engine's ground rule defines it: the highest floor no higher than the feet plus the step,
    /// then again from that floor while it is above the feet, until no floor within a step of it is higher. Null
    /// when there is none, or a floor lies within <paramref name="tolerance"/> of one of the ceilings used (a tie).
    /// </summary>
    public double? AtRest(double x, double y, double feet, double step, double tolerance)
    {
        double ceiling = feet + step;
        if (NearLevel(x, y, ceiling, tolerance))
        {
            return null;
        }

        double? ground = TopZ(x, y, ceiling);
        while (ground is double g && g > feet && g + step > ceiling)
        {
            ceiling = g + step;
            if (NearLevel(x, y, ceiling, tolerance))
            {
                return null;
            }

            ground = TopZ(x, y, ceiling);
            if (ground == g)
            {
                break;
            }
        }

        return ground;
    }

    /// <summary>Whether a floor under (x, y) lies within <paramref name="tolerance"/> of <paramref name="level"/>.</summary>
    public bool NearLevel(double x, double y, double level, double tolerance) =>
        _floors.Exists(f => f.Contains(x, y) && Math.Abs(f.PlaneZ(x, y) - level) < tolerance);

    /// <summary>The horizontal distance from (x, y) to the nearest edge of any floor polygon's outline.</summary>
    public double EdgeDistance(double x, double y)
    {
        double best = double.MaxValue;
        foreach (Floor f in _floors)
        {
            for (int i = 0; i < f.Vertices.Length; i++)
            {
                best = Math.Min(best, ReferenceFloor.Segment(x, y, f.Vertices[i], f.Vertices[(i + 1) % f.Vertices.Length]));
            }
        }

        return best;
    }

    private sealed record Floor((double X, double Y, double Z)[] Vertices, (double X, double Y, double Z) Normal, (double X, double Y, double Z) Mean)
    {
        public double PlaneZ(double x, double y) => Mean.Z - (((Normal.X * (x - Mean.X)) + (Normal.Y * (y - Mean.Y))) / Normal.Z);

        /// <summary>Inside one of the fan triangles (exact barycentric weights all ≥ 0).</summary>
        public bool Contains(double x, double y)
        {
            for (int i = 1; i + 1 < Vertices.Length; i++)
            {
                var (a, b, c) = (Vertices[0], Vertices[i], Vertices[i + 1]);
                double det = ((b.Y - c.Y) * (a.X - c.X)) + ((c.X - b.X) * (a.Y - c.Y));
                if (det == 0)
                {
                    continue;
                }

                double wa = (((b.Y - c.Y) * (x - c.X)) + ((c.X - b.X) * (y - c.Y))) / det;
                double wb = (((c.Y - a.Y) * (x - c.X)) + ((a.X - c.X) * (y - c.Y))) / det;
                if (wa >= 0 && wb >= 0 && 1 - wa - wb >= 0)
                {
                    return true;
                }
            }

            return false;
        }
    }
}
