using System.Numerics;
using AcDream.Core.Physics;

namespace AcDream.Core.Tests.Drawing;

/// <summary>One drawn line (two points) or triangle (three), as the sink received it.</summary>
internal sealed record Drawn(DrawKind Kind, uint Id, Vector3[] Points);

/// <summary>A sink that keeps everything drawn, in order.</summary>
internal sealed class RecordingSink : IDebugSink
{
    public List<Drawn> All { get; } = [];

    public void Line(Vector3 a, Vector3 b, DrawKind kind, uint id) => All.Add(new Drawn(kind, id, [a, b]));

    public void Triangle(Vector3 a, Vector3 b, Vector3 c, DrawKind kind, uint id) => All.Add(new Drawn(kind, id, [a, b, c]));

    public IEnumerable<Drawn> Of(DrawKind kind) => All.Where(d => d.Kind == kind);
}

/// <summary>A sink that allocates nothing: counts per kind, and the last line of each kind.</summary>
internal sealed class CountingSink : IDebugSink
{
    public int[] Counts { get; } = new int[16];

    public (Vector3 A, Vector3 B)[] LastLine { get; } = new (Vector3, Vector3)[16];

    public void Line(Vector3 a, Vector3 b, DrawKind kind, uint id)
    {
        Counts[(int)kind]++;
        LastLine[(int)kind] = (a, b);
    }

    public void Triangle(Vector3 a, Vector3 b, Vector3 c, DrawKind kind, uint id) => Counts[(int)kind]++;
}

/// <summary>A struct sink: counts only (called without boxing).</summary>
internal struct CountingStruct : IDebugSink
{
    public int Lines;
    public int Triangles;

    public void Line(Vector3 a, Vector3 b, DrawKind kind, uint id) => Lines++;

    public void Triangle(Vector3 a, Vector3 b, Vector3 c, DrawKind kind, uint id) => Triangles++;
}

/// <summary>Distances from points to polygons and triangles, metres.</summary>
internal static class Distances
{
    /// <summary>The distance from <paramref name="p"/> to the (planar, fan-triangulated) polygon <paramref name="v"/>.</summary>
    public static float ToPolygon(Vector3 p, IReadOnlyList<Vector3> v)
    {
        if (v.Count == 2)
        {
            return ToSegment(p, v[0], v[1]);
        }

        float best = float.MaxValue;
        for (int i = 1; i + 1 < v.Count; i++)
        {
            best = MathF.Min(best, ToTriangle(p, v[0], v[i], v[i + 1]));
        }

        return best;
    }

    public static float ToSegment(Vector3 p, Vector3 a, Vector3 b)
    {
        Vector3 ab = b - a;
        float t = ab.LengthSquared() == 0f ? 0f : Math.Clamp(Vector3.Dot(p - a, ab) / ab.LengthSquared(), 0f, 1f);
        return Vector3.Distance(p, a + (ab * t));
    }

    /// <summary>The distance from <paramref name="p"/> to triangle a, b, c (its closest point: inside, on an edge or a corner).</summary>
    public static float ToTriangle(Vector3 p, Vector3 a, Vector3 b, Vector3 c)
    {
        Vector3 n = Vector3.Cross(b - a, c - a);
        if (n.LengthSquared() > 1e-12f)
        {
            n = Vector3.Normalize(n);
            float d = Vector3.Dot(p - a, n);
            Vector3 q = p - (n * d);
            if (Inside(q, a, b, n) && Inside(q, b, c, n) && Inside(q, c, a, n))
            {
                return MathF.Abs(d);
            }
        }

        return MathF.Min(ToSegment(p, a, b), MathF.Min(ToSegment(p, b, c), ToSegment(p, c, a)));

        static bool Inside(Vector3 q, Vector3 from, Vector3 to, Vector3 n) => Vector3.Dot(Vector3.Cross(to - from, q - from), n) >= 0f;
    }

    /// <summary>Half the float spacing of a world point's coordinates, as a length: how far rounding to the world frame may move it.</summary>
    public static float Rounding(Vector3 world) =>
        0.5f * new Vector3(Spacing(world.X), Spacing(world.Y), Spacing(world.Z)).Length();

    private static float Spacing(float x) => MathF.BitIncrement(MathF.Abs(x)) - MathF.Abs(x);
}
