using System.Numerics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics.Surfaces;

/// <summary>
/// One walkable triangle, prepared at construction so a query is arithmetic only: landblock-local
/// vertices, the reciprocal lengths of its edges for metre-exact inside tests, the plane that gives
/// its Z, and its bounds. Vertices are counter-clockwise seen from above.
/// </summary>
internal readonly struct FloorTriangle
{
    public readonly Vector2 A;
    public readonly Vector2 B;
    public readonly Vector2 C;

    /// <summary>1 / |BC|, 1 / |CA|, 1 / |AB|: turn edge cross products into distances in metres.</summary>
    public readonly float InvLenBc;
    public readonly float InvLenCa;
    public readonly float InvLenAb;

    /// <summary>Bounds in XY, grown by <see cref="PhysicsConstants.EdgeTolerance"/>.</summary>
    public readonly Vector2 Min;
    public readonly Vector2 Max;

    /// <summary>The plane: Z = <see cref="PlaneZ"/> + <see cref="Gradient"/> · ((x, y) − <see cref="PlanePoint"/>).</summary>
    public readonly Vector2 PlanePoint;
    public readonly float PlaneZ;
    public readonly Vector2 Gradient;

    /// <summary>Lowest and highest vertex Z: a sample never leaves this range.</summary>
    public readonly float ZMin;
    public readonly float ZMax;

    private FloorTriangle(Vector3 a, Vector3 b, Vector3 c, FloorPlane plane)
    {
        A = new Vector2(a.X, a.Y);
        B = new Vector2(b.X, b.Y);
        C = new Vector2(c.X, c.Y);
        InvLenBc = (float)(1.0 / Distance(b, c));
        InvLenCa = (float)(1.0 / Distance(c, a));
        InvLenAb = (float)(1.0 / Distance(a, b));
        var tol = new Vector2(PhysicsConstants.EdgeTolerance);
        Min = Vector2.Min(A, Vector2.Min(B, C)) - tol;
        Max = Vector2.Max(A, Vector2.Max(B, C)) + tol;
        PlanePoint = plane.Point;
        PlaneZ = plane.Z;
        Gradient = plane.Gradient;
        ZMin = MathF.Min(a.Z, MathF.Min(b.Z, c.Z));
        ZMax = MathF.Max(a.Z, MathF.Max(b.Z, c.Z));
    }

    /// <summary>
    /// Builds the triangle (a, b, c) in landblock-local metres, its Z from <paramref name="plane"/>
    /// (the polygon's plane) or, when null, from its own vertices; or returns false when it cannot
    /// carry a floor: it faces down, its area seen from above is below <see cref="PhysicsConstants.MinFloorDoubleArea"/>
    /// (zero-area, collinear, duplicated vertex), or it is a sliver thinner than
    /// <see cref="PhysicsConstants.EdgeTolerance"/> (its whole inside is within the tolerance of its
    /// longest edge, where the neighbouring triangle answers; rounding alone decides its own shape).
    /// </summary>
    public static bool TryCreate(Vector3 a, Vector3 b, Vector3 c, FloorPlane? plane, out FloorTriangle triangle)
    {
        double abx = (double)b.X - a.X, aby = (double)b.Y - a.Y;
        double acx = (double)c.X - a.X, acy = (double)c.Y - a.Y;
        double doubleArea = (abx * acy) - (aby * acx);
        double longest = Math.Max(Distance(a, b), Math.Max(Distance(b, c), Distance(c, a)));
        if (!(doubleArea >= PhysicsConstants.MinFloorDoubleArea) || !(doubleArea / longest >= PhysicsConstants.EdgeTolerance))
        {
            triangle = default;
            return false;
        }

        triangle = new FloorTriangle(a, b, c, plane ?? FloorPlane.Through(a, b, c, doubleArea));
        return true;
    }

    /// <summary>
    /// Z at (x, y) when the point is on the triangle, its edges or within
    /// <see cref="PhysicsConstants.EdgeTolerance"/> of them; otherwise false. Z is the plane's at the
    /// point, clamped to the vertices' Z range: every triangle of a planar polygon answers with the
    /// same formula, so Z is continuous across the polygon's inner edges bit for bit, and a thin
    /// triangle's shape never enters it.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public bool TrySample(float x, float y, out float z)
    {
        var p = new Vector2(x, y);
        if (p.X < Min.X || p.Y < Min.Y || p.X > Max.X || p.Y > Max.Y)
        {
            z = 0f;
            return false;
        }

        // Signed distances (metres, positive inside) to the lines BC, CA and AB.
        float dA = Cross(C - B, p - B) * InvLenBc;
        float dB = Cross(A - C, p - C) * InvLenCa;
        float dC = Cross(B - A, p - A) * InvLenAb;
        const float tol = -PhysicsConstants.EdgeTolerance;
        if (dA < tol || dB < tol || dC < tol)
        {
            z = 0f;
            return false;
        }

        z = Math.Clamp(PlaneZ + Vector2.Dot(Gradient, p - PlanePoint), ZMin, ZMax);
        return true;
    }

    /// <summary>
    /// The point of the triangle (seen from above, edges included) nearest <paramref name="p"/>: <paramref name="p"/>
    /// itself when it is over the triangle (within <see cref="PhysicsConstants.EdgeTolerance"/>), else the nearest point of
    /// its nearest edge. Landblock-local metres.
    /// </summary>
    public Vector2 Nearest(Vector2 p)
    {
        float dA = Cross(C - B, p - B) * InvLenBc;
        float dB = Cross(A - C, p - C) * InvLenCa;
        float dC = Cross(B - A, p - A) * InvLenAb;
        const float tol = -PhysicsConstants.EdgeTolerance;
        if (dA >= tol && dB >= tol && dC >= tol)
        {
            return p;
        }

        Vector2 best = OnSegment(A, B, p), candidate = OnSegment(B, C, p);
        best = Vector2.DistanceSquared(candidate, p) < Vector2.DistanceSquared(best, p) ? candidate : best;
        candidate = OnSegment(C, A, p);
        return Vector2.DistanceSquared(candidate, p) < Vector2.DistanceSquared(best, p) ? candidate : best;
    }

    /// <summary>
    /// The triangle's Z for a body centred at <paramref name="centre"/> that it holds (footing): its plane under the centre, no
    /// higher than its highest vertex. The plane is not clamped from below: the triangles of one slope, or of a run of sloped
    /// pieces in one plane, give the same Z as the one under the centre, so footing lifts the body only onto what is higher.
    /// </summary>
    public float UnderCentre(Vector2 centre) => MathF.Min(PlaneZ + Vector2.Dot(Gradient, centre - PlanePoint), ZMax);

    /// <summary>The point of segment a–b nearest <paramref name="p"/>.</summary>
    private static Vector2 OnSegment(Vector2 a, Vector2 b, Vector2 p)
    {
        Vector2 ab = b - a;
        float length = Vector2.Dot(ab, ab);
        float t = length > 0f ? Math.Clamp(Vector2.Dot(p - a, ab) / length, 0f, 1f) : 0f;
        return new Vector2(a.X + (ab.X * t), a.Y + (ab.Y * t));
    }

    /// <summary>The Z of the triangle's plane at (x, y), anywhere (not clamped, not only over the triangle).</summary>
    public float PlaneAt(Vector2 p) => PlaneZ + Vector2.Dot(Gradient, p - PlanePoint);

    /// <summary>The unit normal of the plane the triangle samples (pointing up).</summary>
    public Vector3 Normal => Vector3.Normalize(new Vector3(-Gradient.X, -Gradient.Y, 1f));

    /// <summary>The triangle's Z at vertex (x, y) of it: its plane, clamped to its Z range, as a sample there gives.</summary>
    public float ZAt(Vector2 vertex) => Math.Clamp(PlaneZ + Vector2.Dot(Gradient, vertex - PlanePoint), ZMin, ZMax);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static float Cross(Vector2 u, Vector2 v) => (u.X * v.Y) - (u.Y * v.X);

    private static double Distance(Vector3 u, Vector3 v)
    {
        double dx = (double)u.X - v.X, dy = (double)u.Y - v.Y;
        return Math.Sqrt((dx * dx) + (dy * dy));
    }
}

/// <summary>
/// A non-vertical plane as Z over XY: Z = <see cref="Z"/> + <see cref="Gradient"/> · ((x, y) − <see cref="Point"/>),
/// landblock-local metres.
/// </summary>
internal readonly record struct FloorPlane(Vector2 Point, float Z, Vector2 Gradient)
{
    /// <summary>
    /// The plane of a floor polygon (unit <paramref name="normal"/> with Z ≥ FloorZ) through the mean
    /// of its vertices, or null when a vertex lies farther than <see cref="PhysicsConstants.EdgeTolerance"/>
    /// from it (a non-planar polygon, whose triangles then use their own planes).
    /// </summary>
    public static FloorPlane? OfPolygon(ReadOnlySpan<Vector3> vertices, Vector3 normal)
    {
        double cx = 0, cy = 0, cz = 0;
        foreach (Vector3 v in vertices)
        {
            cx += v.X;
            cy += v.Y;
            cz += v.Z;
        }

        cx /= vertices.Length;
        cy /= vertices.Length;
        cz /= vertices.Length;
        foreach (Vector3 v in vertices)
        {
            double distance = (normal.X * (v.X - cx)) + (normal.Y * (v.Y - cy)) + (normal.Z * (v.Z - cz));
            if (!(Math.Abs(distance) <= PhysicsConstants.EdgeTolerance))
            {
                return null;
            }
        }

        // The reference point is stored as floats: move its Z along the plane to where it was rounded.
        double gx = -(double)normal.X / normal.Z, gy = -(double)normal.Y / normal.Z;
        var point = new Vector2((float)cx, (float)cy);
        double z = cz + (gx * (point.X - cx)) + (gy * (point.Y - cy));
        return new FloorPlane(point, (float)z, new Vector2((float)gx, (float)gy));
    }

    /// <summary>The plane through a triangle of twice-area <paramref name="doubleArea"/> &gt; 0 seen from above, computed in double.</summary>
    public static FloorPlane Through(Vector3 a, Vector3 b, Vector3 c, double doubleArea)
    {
        double abx = (double)b.X - a.X, aby = (double)b.Y - a.Y, abz = (double)b.Z - a.Z;
        double acx = (double)c.X - a.X, acy = (double)c.Y - a.Y, acz = (double)c.Z - a.Z;

        // Normal = AB × AC; its Z is the twice-area; the gradient is −(nx, ny) / nz.
        double nx = (aby * acz) - (abz * acy);
        double ny = (abz * acx) - (abx * acz);
        return new FloorPlane(new Vector2(a.X, a.Y), a.Z, new Vector2((float)(-nx / doubleArea), (float)(-ny / doubleArea)));
    }
}
