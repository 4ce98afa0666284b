using System.Numerics;

namespace AcDream.Core.Physics.Surfaces;

/// <summary>Small geometric helpers shared by the surfaces. Allocation-free.</summary>
internal static class Geometry
{
    /// <summary>
    /// Unit normal of a polygon by Newell's method (the winding normal: counter-clockwise seen from
    /// above gives +Z), computed in double about <paramref name="centre"/>; <see cref="Vector3.Zero"/>
    /// when the polygon has no area. Unlike <c>cross(v1 − v0, v2 − v0)</c> it does not depend on the
    /// first three vertices being non-collinear, and it averages a non-planar polygon.
    /// </summary>
    public static Vector3 NewellNormal(ReadOnlySpan<Vector3> vertices, Vector3 centre)
    {
        double nx = 0, ny = 0, nz = 0;
        for (int i = 0; i < vertices.Length; i++)
        {
            Vector3 a = vertices[i] - centre;
            Vector3 b = vertices[(i + 1) % vertices.Length] - centre;
            nx += ((double)a.Y - b.Y) * ((double)a.Z + b.Z);
            ny += ((double)a.Z - b.Z) * ((double)a.X + b.X);
            nz += ((double)a.X - b.X) * ((double)a.Y + b.Y);
        }

        double length = Math.Sqrt((nx * nx) + (ny * ny) + (nz * nz));
        if (!(length > PhysicsConstants.MinFloorDoubleArea))
        {
            return Vector3.Zero;
        }

        return new Vector3((float)(nx / length), (float)(ny / length), (float)(nz / length));
    }

    /// <summary>
    /// Whether <paramref name="p"/> is inside the polygon <paramref name="outline"/> (even-odd rule,
    /// any winding, convex or not) or within <paramref name="tolerance"/> metres of one of its edges.
    /// </summary>
    public static bool PolygonContains(ReadOnlySpan<Vector2> outline, Vector2 p, float tolerance)
    {
        bool inside = false;
        float tol2 = tolerance * tolerance;
        for (int i = 0, j = outline.Length - 1; i < outline.Length; j = i++)
        {
            Vector2 a = outline[j];
            Vector2 b = outline[i];
            if (DistanceSquaredToSegment(p, a, b) <= tol2)
            {
                return true;
            }

            if ((b.Y > p.Y) != (a.Y > p.Y) && p.X < a.X + ((p.Y - a.Y) * (b.X - a.X) / (b.Y - a.Y)))
            {
                inside = !inside;
            }
        }

        return inside;
    }

    /// <summary>Whether <paramref name="p"/> is inside polygon <paramref name="v"/> seen from above (even-odd rule, any winding; an edge's points count or not as rounding falls).</summary>
    public static bool InsidePolygonXY(ReadOnlySpan<Vector3> v, Vector2 p)
    {
        bool inside = false;
        for (int i = 0, j = v.Length - 1; i < v.Length; j = i++)
        {
            Vector3 a = v[j], b = v[i];
            if ((b.Y > p.Y) != (a.Y > p.Y) && p.X < a.X + ((p.Y - a.Y) * (b.X - a.X) / (b.Y - a.Y)))
            {
                inside = !inside;
            }
        }

        return inside;
    }

    /// <summary>Squared distance from <paramref name="p"/> to the segment a–b (a point when a = b).</summary>
    public static float DistanceSquaredToSegment(Vector2 p, Vector2 a, Vector2 b)
    {
        Vector2 ab = b - a;
        float lengthSquared = ab.LengthSquared();
        float t = lengthSquared > 0f ? Math.Clamp(Vector2.Dot(p - a, ab) / lengthSquared, 0f, 1f) : 0f;
        return Vector2.DistanceSquared(p, a + (ab * t));
    }

    /// <summary>Whether every coordinate of <paramref name="v"/> is finite.</summary>
    public static bool IsFinite(Vector3 v) => float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z);

    /// <summary>
    /// <c>MathF.BitIncrement(x) − x</c> for <paramref name="x"/> ≥ 0, bit for bit: the spacing of floats at x, from the
    /// exponent's bits alone where that spacing is a normal float and x is below <see cref="float.MaxValue"/>
    /// (every length the engine asks it of), else by the increment itself.
    /// </summary>
    [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
    public static float Spacing(float x)
    {
        int exponent = BitConverter.SingleToInt32Bits(x) & 0x7F800000;
        return exponent > (23 << 23) && x < float.MaxValue
            ? BitConverter.Int32BitsToSingle(exponent - (23 << 23))
            : MathF.BitIncrement(x) - x;
    }
}
