using System.Numerics;
using AcDream.Core.Physics;

namespace AcDream.Testing;

/// <summary>
/// Footing (<see cref="MovementOptions.Footing"/>) in double precision, from the floors the engine publishes: whether
/// a floor triangle holds a body centred at a landblock-local point with its feet at a height. It holds it when its
/// nearest point seen from above is within the support reach (half the radius) and its plane under the centre,
/// no higher than its highest vertex, is at the feet (within the ground tolerance).
/// </summary>
internal static class FootingReference
{
    /// <summary>Whether one of <paramref name="floors"/> holds a body of radius <paramref name="radius"/> centred at <paramref name="p"/> with its feet at <paramref name="z"/>.</summary>
    public static bool Holds(IEnumerable<FloorTriangleInfo> floors, Vector2 p, double z, double radius)
    {
        double reach = radius * PhysicsConstants.SupportReach;
        foreach (FloorTriangleInfo t in floors)
        {
            if (Distance(t, p.X, p.Y) <= reach + 1e-5 && Math.Abs(ZUnder(t, p.X, p.Y) - z) <= PhysicsConstants.GroundTolerance + 1e-5)
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>
    /// Whether a body of <paramref name="options"/> (with footing; false without it) standing at <paramref name="r"/> (its
    /// landblock-local <paramref name="local"/>) is held by a floor under its footprint: indoors the floors of the cells
    /// given (its building's) and of the objects in them, outdoors those of the outdoor objects and of every cell.
    /// </summary>
    public static bool HoldsAnswer(MovementOptions options, IEnumerable<CellSurface> cells, IEnumerable<ObjectSurface> objects, ResolveResult r, Vector2 local)
    {
        if (!options.Footing || options.Body is not MoverBody body)
        {
            return false;
        }

        uint cell = CellIds.IsIndoor(r.CellId) ? r.CellId : 0;
        // Indoors its cell, and (it may have been in the air before its footing held it) the other cells of the building.
        HashSet<uint> near = cell == 0 ? [0] : [cell, .. cells.Select(c => c.CellId)];
        IEnumerable<FloorTriangleInfo> floors = objects.Where(o => near.Contains(o.CellId)).SelectMany(o => o.GetFloorTriangles());
        floors = floors.Concat(cells.Where(c => cell == 0 || near.Contains(c.CellId)).SelectMany(c => c.GetFloorTriangles()));

        return Holds(floors, local, r.Position.Z, body.Radius);
    }

    /// <summary>The triangle's plane at (x, y), no higher than its highest vertex.</summary>
    public static double ZUnder(FloorTriangleInfo t, double x, double y)
    {
        double abx = t.B.X - t.A.X, aby = t.B.Y - t.A.Y, abz = t.B.Z - t.A.Z;
        double acx = t.C.X - t.A.X, acy = t.C.Y - t.A.Y, acz = t.C.Z - t.A.Z;
        double nx = (aby * acz) - (abz * acy), ny = (abz * acx) - (abx * acz), nz = (abx * acy) - (aby * acx);
        double z = t.A.Z - (((nx * (x - t.A.X)) + (ny * (y - t.A.Y))) / nz);
        return Math.Min(z, Math.Max(t.A.Z, Math.Max(t.B.Z, t.C.Z)));
    }

    /// <summary>Distance seen from above from (x, y) to the triangle: 0 inside.</summary>
    public static double Distance(FloorTriangleInfo t, double x, double y)
    {
        double d1 = Side(t.A, t.B, x, y), d2 = Side(t.B, t.C, x, y), d3 = Side(t.C, t.A, x, y);
        bool anyNegative = d1 < 0 || d2 < 0 || d3 < 0, anyPositive = d1 > 0 || d2 > 0 || d3 > 0;
        if (!(anyNegative && anyPositive))
        {
            return 0;
        }

        return Math.Min(Segment(t.A, t.B, x, y), Math.Min(Segment(t.B, t.C, x, y), Segment(t.C, t.A, x, y)));
    }

    private static double Side(Vector3 a, Vector3 b, double x, double y) => ((b.X - (double)a.X) * (y - a.Y)) - ((b.Y - (double)a.Y) * (x - a.X));

    private static double Segment(Vector3 a, Vector3 b, double x, double y)
    {
        double dx = b.X - (double)a.X, dy = b.Y - (double)a.Y;
        double length = (dx * dx) + (dy * dy);
        double s = length > 0 ? Math.Clamp((((x - a.X) * dx) + ((y - a.Y) * dy)) / length, 0, 1) : 0;
        double ex = a.X + (dx * s) - x, ey = a.Y + (dy * s) - y;
        return Math.Sqrt((ex * ex) + (ey * ey));
    }
}
