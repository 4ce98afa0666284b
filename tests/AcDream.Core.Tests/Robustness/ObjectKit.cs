using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;

namespace AcDream.Core.Tests.Robustness;

/// <summary>Builders for synthetic objects, and a double-precision reference for object floors.</summary>
internal static class ObjectKit
{
    /// <summary>A GfxObj from polygons given as vertex loops (object-local), each polygon with its own vertices.</summary>
    public static GfxObj Gfx(uint id, params Vector3[][] polygons) =>
        AcDream.Testing.DeterminismWalk.AddPhysicsPolygons(new GfxObj { Id = id, Flags = GfxObjFlags.HasPhysics }, polygons);

    /// <summary>A tree: a Setup of one part with no polygons and one cylinder.</summary>
    public static (Setup Setup, Dictionary<uint, GfxObj> Parts) Tree(float radius = 0.4f, float height = 5f)
    {
        var trunk = new GfxObj { Id = 0x01000001 };
        var setup = new Setup
        {
            Id = 0x02000001,
            NumParts = 1,
            Parts = [trunk.Id],
            CylSpheres = [new CylSphere { Origin = Vector3.Zero, Radius = radius, Height = height }],
        };
        return (setup, new Dictionary<uint, GfxObj> { [trunk.Id] = trunk });
    }

    public static Frame At(Vector3 origin, Quaternion orientation) => new() { Origin = origin, Orientation = orientation };

    public static Frame At(Vector3 origin, float yawRadians) => At(origin, Quaternion.CreateFromAxisAngle(Vector3.UnitZ, yawRadians));

    /// <summary>Object-local → landblock-local in double precision (the orientation normalised in double).</summary>
    public static (double X, double Y, double Z) Place(Frame frame, Vector3 v)
    {
        Quaternion q = frame.Orientation;
        double qx = q.X, qy = q.Y, qz = q.Z, qw = q.W;
        double n = Math.Sqrt((qx * qx) + (qy * qy) + (qz * qz) + (qw * qw));
        (qx, qy, qz, qw) = (qx / n, qy / n, qz / n, qw / n);
        double vx = v.X, vy = v.Y, vz = v.Z;
        double cx = (qy * vz) - (qz * vy), cy = (qz * vx) - (qx * vz), cz = (qx * vy) - (qy * vx);
        double dx = (qy * cz) - (qz * cy), dy = (qz * cx) - (qx * cz), dz = (qx * cy) - (qy * cx);
        return (frame.Origin.X + vx + (2 * ((qw * cx) + dx)), frame.Origin.Y + vy + (2 * ((qw * cy) + dy)), frame.Origin.Z + vz + (2 * ((qw * cz) + dz)));
    }

    /// <summary>A GfxObj's floors placed by a frame, in double precision.</summary>
    public static List<RefFloor> Floors(GfxObj gfx, Frame frame)
    {
        var result = new List<RefFloor>();
        foreach (Polygon polygon in gfx.PhysicsPolygons.Values)
        {
            var v = polygon.VertexIds.Select(i => Place(frame, gfx.VertexArray.Vertices[(ushort)i].Origin)).ToArray();
            double nx = 0, ny = 0, nz = 0;
            for (int i = 0; i < v.Length; i++)
            {
                var a = v[i];
                var b = v[(i + 1) % v.Length];
                nx += (a.Y - b.Y) * (a.Z + b.Z);
                ny += (a.Z - b.Z) * (a.X + b.X);
                nz += (a.X - b.X) * (a.Y + b.Y);
            }

            double length = Math.Sqrt((nx * nx) + (ny * ny) + (nz * nz));
            if (length < 1e-9)
            {
                continue;
            }

            (nx, ny, nz) = (nx / length, ny / length, nz / length);
            result.Add(new RefFloor(v, nx, ny, nz, nz >= PhysicsConstants.FloorZ));
        }

        return result;
    }

    /// <summary>
    /// The reference ground a mover with its feet at <paramref name="feet"/> and step <paramref name="step"/> comes
    /// to rest on at (x, y): <see cref="Ground"/> for feet + step, then again from the ground found while it is
    /// above the feet and lifts the ceiling (a step from a step), until nothing higher is within a step. Null
    /// where any of those passes is in doubt.
    /// </summary>
    public static double? AtRest(IEnumerable<RefFloor> floors, double x, double y, double feet, double step, double terrain, double margin = 1e-3)
    {
        double ceiling = feet + step;
        double? ground = Ground(floors, x, y, ceiling, terrain, margin);
        while (ground is double g && g > feet && g + step > ceiling)
        {
            ceiling = g + step;
            ground = Ground(floors, x, y, ceiling, terrain, margin);
            if (ground == g)
            {
                break;
            }
        }

        return ground;
    }

    /// <summary>
    /// The reference ground under (x, y) for feet + step = <paramref name="ceiling"/>: the highest walkable
    /// polygon's plane there no higher than the ceiling, when above <paramref name="terrain"/>. Null when
    /// (x, y) is within <paramref name="margin"/> of a floor's edge, a candidate within the margin of the
    /// ceiling, or a polygon's walkability within 1e-3 of the limit: the engine's tolerances may go either way there.
    /// </summary>
    public static double? Ground(IEnumerable<RefFloor> floors, double x, double y, double ceiling, double terrain, double margin = 1e-3)
    {
        double best = terrain;
        foreach (RefFloor f in floors)
        {
            if (x < f.MinX - margin || x > f.MaxX + margin || y < f.MinY - margin || y > f.MaxY + margin)
            {
                continue;
            }

            double edge = f.SignedInside(x, y);
            if (Math.Abs(edge) < margin)
            {
                return null;
            }

            if (edge < 0)
            {
                continue;
            }

            if (Math.Abs(f.Nz - PhysicsConstants.FloorZ) < 1e-3)
            {
                return null;
            }

            if (!f.Walkable)
            {
                continue;
            }

            double z = f.ZAt(x, y);
            if (Math.Abs(z - ceiling) < margin || Math.Abs(z - terrain) < margin)
            {
                return null;
            }

            if (z <= ceiling && z > best)
            {
                best = z;
            }
        }

        return best;
    }
}

/// <summary>One placed polygon in double precision: its vertices and unit winding normal.</summary>
internal sealed record RefFloor((double X, double Y, double Z)[] V, double Nx, double Ny, double Nz, bool Walkable)
{
    public double MinX { get; } = V.Min(v => v.X);

    public double MaxX { get; } = V.Max(v => v.X);

    public double MinY { get; } = V.Min(v => v.Y);

    public double MaxY { get; } = V.Max(v => v.Y);

    public double ZAt(double x, double y) => V[0].Z - (((Nx * (x - V[0].X)) + (Ny * (y - V[0].Y))) / Nz);

    /// <summary>Distance inside the (convex) XY outline: positive inside, negative outside (for an upward polygon).</summary>
    public double SignedInside(double x, double y)
    {
        double sign = Nz >= 0 ? 1 : -1, inside = double.MaxValue;
        for (int i = 0; i < V.Length; i++)
        {
            var a = V[i];
            var b = V[(i + 1) % V.Length];
            double ex = b.X - a.X, ey = b.Y - a.Y, len = Math.Sqrt((ex * ex) + (ey * ey));
            if (len < 1e-12)
            {
                continue;
            }

            inside = Math.Min(inside, sign * ((ex * (y - a.Y)) - (ey * (x - a.X))) / len);
        }

        return inside;
    }
}
