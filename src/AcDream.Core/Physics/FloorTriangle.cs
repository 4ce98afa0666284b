using System.Numerics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics;

/// <summary>
/// One walkable triangle, prepared at construction so a query is arithmetic only: landblock-local
/// vertices, the reciprocal lengths of its edges for metre-exact inside tests, and its bounds.
/// Vertices are counter-clockwise seen from above.
/// </summary>
internal readonly struct FloorTriangle
{
    public readonly Vector2 A;
    public readonly Vector2 B;
    public readonly Vector2 C;
    public readonly float Za;
    public readonly float Zb;
    public readonly float Zc;

    /// <summary>1 / |BC|, 1 / |CA|, 1 / |AB|: turn edge cross products into distances in metres.</summary>
    public readonly float InvLenBc;
    public readonly float InvLenCa;
    public readonly float InvLenAb;

    /// <summary>Bounds in XY, grown by <see cref="PhysicsConstants.EdgeTolerance"/>.</summary>
    public readonly Vector2 Min;
    public readonly Vector2 Max;

    private FloorTriangle(Vector3 a, Vector3 b, Vector3 c)
    {
        A = new Vector2(a.X, a.Y);
        B = new Vector2(b.X, b.Y);
        C = new Vector2(c.X, c.Y);
        Za = a.Z;
        Zb = b.Z;
        Zc = c.Z;
        InvLenBc = 1f / Vector2.Distance(B, C);
        InvLenCa = 1f / Vector2.Distance(C, A);
        InvLenAb = 1f / Vector2.Distance(A, B);
        var tol = new Vector2(PhysicsConstants.EdgeTolerance);
        Min = Vector2.Min(A, Vector2.Min(B, C)) - tol;
        Max = Vector2.Max(A, Vector2.Max(B, C)) + tol;
    }

    /// <summary>
    /// Builds the triangle (a, b, c) in landblock-local metres, or returns false when it cannot
    /// carry a floor: its area seen from above is below <see cref="MinDoubleArea"/> (zero-area,
    /// collinear, duplicated vertex) or it faces down.
    /// </summary>
    public static bool TryCreate(Vector3 a, Vector3 b, Vector3 c, out FloorTriangle triangle)
    {
        double abx = (double)b.X - a.X, aby = (double)b.Y - a.Y;
        double acx = (double)c.X - a.X, acy = (double)c.Y - a.Y;
        double doubleArea = (abx * acy) - (aby * acx);
        if (!(doubleArea >= MinDoubleArea))
        {
            triangle = default;
            return false;
        }

        triangle = new FloorTriangle(a, b, c);
        return true;
    }

    /// <summary>
    /// Smallest twice-area (m²) seen from above of a triangle that carries a floor: 1e-8 m², a
    /// triangle 0.1 mm wide over 0.1 m. Anything smaller is rounding, not a surface.
    /// </summary>
    public const double MinDoubleArea = 1e-8;

    /// <summary>
    /// Z at (x, y) when the point is on the triangle, its edges or within
    /// <see cref="PhysicsConstants.EdgeTolerance"/> of them; otherwise false. Z is the barycentric
    /// blend of the vertex Zs with weights clamped to the triangle, so it always lies between the
    /// lowest and highest vertex, even for a sliver.
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

        // Weight of a vertex ∝ distance to the opposite edge × that edge's length.
        float wA = MathF.Max(dA, 0f) / InvLenBc;
        float wB = MathF.Max(dB, 0f) / InvLenCa;
        float wC = MathF.Max(dC, 0f) / InvLenAb;
        float sum = wA + wB + wC;
        if (!(sum > 0f))
        {
            // Only reachable for a point on a vertex of a sliver: all weights rounded to zero.
            z = Za;
            return true;
        }

        z = ((wA * Za) + (wB * Zb) + (wC * Zc)) / sum;
        return true;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static float Cross(Vector2 u, Vector2 v) => (u.X * v.Y) - (u.Y * v.X);
}
