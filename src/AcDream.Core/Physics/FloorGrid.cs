using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>
/// A uniform XY grid over a cell's floor triangles, built once at construction: each grid square
/// lists the triangles whose (tolerance-grown) bounds overlap it, so a query tests only the few
/// triangles near the point. The answer is the brute-force one: every triangle that could contain
/// the point is listed in the point's square, and the floor selection does not depend on order.
/// </summary>
internal sealed class FloorGrid
{
    /// <summary>Below this many triangles a plain loop is faster than the grid lookup.</summary>
    public const int MinTriangles = 16;

    private const int MaxSide = 64;

    private readonly Vector2 _min;
    private readonly Vector2 _inverseSize;
    private readonly int _columns;
    private readonly int _rows;

    /// <summary>Start of square s's run in <see cref="_items"/>; square s spans [_start[s], _start[s + 1]).</summary>
    private readonly int[] _start;
    private readonly int[] _items;

    public FloorGrid(FloorTriangle[] triangles, Vector2 min, Vector2 max)
    {
        // About one triangle per square on average, squares no smaller than 0.25 m.
        int side = Math.Clamp((int)MathF.Ceiling(MathF.Sqrt(triangles.Length)), 1, MaxSide);
        Vector2 extent = Vector2.Max(max - min, new Vector2(0.25f));
        _columns = Math.Clamp((int)MathF.Ceiling(extent.X / MathF.Max(extent.X, extent.Y) * side), 1, MaxSide);
        _rows = Math.Clamp((int)MathF.Ceiling(extent.Y / MathF.Max(extent.X, extent.Y) * side), 1, MaxSide);
        _min = min;
        _inverseSize = new Vector2(_columns / extent.X, _rows / extent.Y);

        var counts = new int[(_columns * _rows) + 1];
        ForEachSquare(triangles, (square, _) => counts[square + 1]++);
        for (int s = 0; s < _columns * _rows; s++)
        {
            counts[s + 1] += counts[s];
        }

        _start = counts;
        _items = new int[counts[^1]];
        var fill = (int[])counts.Clone();
        ForEachSquare(triangles, (square, triangle) => _items[fill[square]++] = triangle);
    }

    /// <summary>Indices of the triangles that may contain (x, y), in ascending order.</summary>
    public ReadOnlySpan<int> Candidates(float x, float y)
    {
        int column = Math.Clamp((int)((x - _min.X) * _inverseSize.X), 0, _columns - 1);
        int row = Math.Clamp((int)((y - _min.Y) * _inverseSize.Y), 0, _rows - 1);
        int square = (row * _columns) + column;
        return _items.AsSpan(_start[square], _start[square + 1] - _start[square]);
    }

    private void ForEachSquare(FloorTriangle[] triangles, Action<int, int> visit)
    {
        for (int t = 0; t < triangles.Length; t++)
        {
            // Clamping the bounds into the grid keeps every triangle reachable from the squares a
            // query can map to, even one rounding puts a hair outside.
            int c0 = Math.Clamp((int)((triangles[t].Min.X - _min.X) * _inverseSize.X), 0, _columns - 1);
            int c1 = Math.Clamp((int)((triangles[t].Max.X - _min.X) * _inverseSize.X), 0, _columns - 1);
            int r0 = Math.Clamp((int)((triangles[t].Min.Y - _min.Y) * _inverseSize.Y), 0, _rows - 1);
            int r1 = Math.Clamp((int)((triangles[t].Max.Y - _min.Y) * _inverseSize.Y), 0, _rows - 1);
            for (int r = r0; r <= r1; r++)
            {
                for (int c = c0; c <= c1; c++)
                {
                    visit((r * _columns) + c, t);
                }
            }
        }
    }
}
