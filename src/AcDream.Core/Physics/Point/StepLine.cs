using System.Numerics;
using AcDream.Core.Physics.Surfaces;

namespace AcDream.Core.Physics.Point;

/// <summary>
/// A point move's step line: the segment <see cref="P0"/> → <see cref="P1"/> seen from above at height
/// <see cref="H"/> (the feet plus the step: lower walls are steps), with its box; and where it crosses a
/// wall's segment, a cylinder or a polygon cut at that height. Landblock-local metres.
/// </summary>
internal readonly struct StepLine
{
    public readonly Vector2 P0;
    public readonly Vector2 P1;
    public readonly float H;

    /// <summary>The segment's box, seen from above.</summary>
    public readonly Vector2 Lo;

    public readonly Vector2 Hi;

    public StepLine(Vector2 p0, Vector2 p1, float h)
    {
        (P0, P1, H) = (p0, p1, h);
        (Lo, Hi) = (Vector2.Min(p0, p1), Vector2.Max(p0, p1));
    }

    /// <summary>This line moved into a frame whose origin is <paramref name="offset"/> from this one's.</summary>
    public StepLine Less(Vector2 offset) => new(P0 - offset, P1 - offset, H);

    /// <summary>
    /// The first of <paramref name="walls"/> the line crosses (at its height) before <c>hit.T</c>, into
    /// <paramref name="hit"/> (fraction, normal facing the mover, whether a cylinder); true when one is.
    /// </summary>
    public bool FirstCrossing(CellWalls walls, ref ObjectHit hit)
    {
        bool crossed = false;
        ReadOnlySpan<Vector3> vertices = walls.Vertices;
        foreach (ref readonly WallPolygon w in walls.Polygons.AsSpan())
        {
            if (!(w.ZMin < H && w.ZMax > H) || w.Min.X > Hi.X || w.Max.X < Lo.X || w.Min.Y > Hi.Y || w.Max.Y < Lo.Y)
            {
                continue;
            }

            if (w.Radius > 0f)
            {
                if (CrossCircle(w.A, w.Radius, ref hit.T, ref hit.Normal))
                {
                    (crossed, hit.Cylinder) = (true, true);
                }
            }
            else if ((w.IsUpright && CrossSegment(w.A, w.B, ref hit.T, ref hit.Normal))
                || (!w.IsUpright && Cut(vertices.Slice(w.First, w.Count), H, out Vector2 a, out Vector2 b) && CrossSegment(a, b, ref hit.T, ref hit.Normal)))
            {
                (crossed, hit.Cylinder) = (true, false);
            }
        }

        return crossed;
    }

    /// <summary>Where a convex polygon meets the plane z = <paramref name="h"/>: the chord between its extreme crossing points.</summary>
    private static bool Cut(ReadOnlySpan<Vector3> v, float h, out Vector2 a, out Vector2 b)
    {
        (a, b) = (default, default);
        int n = 0;
        for (int i = 0; i < v.Length; i++)
        {
            Vector3 p = v[i], q = v[(i + 1) % v.Length];
            if ((p.Z < h) == (q.Z < h))
            {
                continue;
            }

            float s = (h - p.Z) / (q.Z - p.Z);
            var point = new Vector2(p.X + ((q.X - p.X) * s), p.Y + ((q.Y - p.Y) * s));
            if (n == 0)
            {
                a = point;
            }
            else if (n == 1 || Vector2.DistanceSquared(a, point) > Vector2.DistanceSquared(a, b))
            {
                b = point;
            }

            n++;
        }

        return n >= 2 && a != b;
    }

    /// <summary>The line crosses segment a–b (from either side, onto or through its line, within its ends) before <paramref name="t"/>.</summary>
    private bool CrossSegment(Vector2 a, Vector2 b, ref float t, ref Vector3 normal)
    {
        Vector2 ab = b - a;
        float s0 = Cross(ab, P0 - a), s1 = Cross(ab, P1 - a);
        if (s0 == 0f || (s0 > 0f && s1 > 0f) || (s0 < 0f && s1 < 0f))
        {
            return false; // starts on the line (may leave it) or stays on one side
        }

        float at = s0 / (s0 - s1);
        Vector2 point = P0 + ((P1 - P0) * at);
        float u = Vector2.Dot(point - a, ab) / ab.LengthSquared();
        if (!(u >= 0f && u <= 1f) || !(at < t))
        {
            return false;
        }

        Vector2 n = Vector2.Normalize(s0 > 0f ? new Vector2(-ab.Y, ab.X) : new Vector2(ab.Y, -ab.X));
        (t, normal) = (at, new Vector3(n, 0f));
        return true;
    }

    /// <summary>The line enters the circle (centre <paramref name="c"/>, radius <paramref name="r"/>) before <paramref name="t"/>; a line starting inside may leave.</summary>
    private bool CrossCircle(Vector2 c, float r, ref float t, ref Vector3 normal)
    {
        Vector2 d = P1 - P0, f = P0 - c;
        float a = d.LengthSquared(), b = Vector2.Dot(f, d), k = f.LengthSquared() - (r * r);
        if (k <= 0f || b >= 0f || a == 0f)
        {
            return false; // starts inside (or on) the circle, or moves away from it
        }

        float disc = (b * b) - (a * k);
        if (disc < 0f)
        {
            return false;
        }

        float at = (-b - MathF.Sqrt(disc)) / a;
        if (!(at <= 1f) || !(at < t))
        {
            return false;
        }

        at = MathF.Max(at, 0f);
        Vector2 n = f + (d * at);
        float length = n.Length();
        (t, normal) = (at, length > 0f ? new Vector3(n / length, 0f) : new Vector3(-d / MathF.Sqrt(a), 0f));
        return true;
    }

    private static float Cross(Vector2 u, Vector2 v) => (u.X * v.Y) - (u.Y * v.X);
}
