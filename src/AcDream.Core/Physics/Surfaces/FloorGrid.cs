using System.Numerics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics.Surfaces;

/// <summary>
/// A uniform XY grid over a cell's floor triangles, built once at construction: each grid square
/// lists the triangles whose (tolerance-grown) bounds overlap it, so a query tests only the triangles
/// near the point. The answer is the brute-force one (<see cref="Keep"/> over every triangle): every
/// triangle that could contain the point is listed in the point's square, and a triangle is skipped
/// only when its Z range proves it cannot beat the floor already found.
/// </summary>
/// <remarks>
/// <para>
/// Size: about one triangle per square on average, at most 64 × 64 squares, and at most
/// <see cref="PhysicsConstants.MaxFloorGridEntriesPerTriangle"/> (square, triangle) entries per
/// triangle: where triangles are large (stacked whole-cell floors) the grid is made coarser, since
/// finer squares would only list the same triangles again.
/// </para>
/// <para>
/// Stacks: a square listing more than <see cref="PhysicsConstants.FloorGridLinearScanMax"/> triangles keeps them sorted by
/// their lowest Z, with the highest Z of each prefix, and a query searches outwards from the reference
/// Z (down, then up) until the remaining triangles' Z ranges are farther than the nearest floor found.
/// </para>
/// </remarks>
internal sealed class FloorGrid
{


    private readonly FloorTriangle[] _triangles;
    private readonly Layout _layout;

    /// <summary>Start of square s's run in <see cref="_items"/>; square s spans [_start[s], _start[s + 1]).</summary>
    private readonly int[] _start;

    /// <summary>Triangle indices, square by square; a run longer than <see cref="PhysicsConstants.FloorGridLinearScanMax"/> in order of lowest Z.</summary>
    private readonly int[] _items;

    /// <summary>
    /// Start of square s's Z ranges in <see cref="_z"/>, aligned with its run, as <see cref="_start"/>
    /// (no ranges for a run scanned by a plain loop); empty when no run is longer than <see cref="PhysicsConstants.FloorGridLinearScanMax"/>.
    /// </summary>
    private readonly int[] _zStart;
    private readonly ZRange[] _z;

    /// <summary>Indexes <paramref name="triangles"/> (kept, not copied) within the bounds [min, max].</summary>
    public FloorGrid(FloorTriangle[] triangles, Vector2 min, Vector2 max)
    {
        _triangles = triangles;

        // About one triangle per square on average; then the finest grid (a binary search on the side)
        // within the entry budget. One square (side 1) lists each triangle once, so it always fits.
        long budget = (long)PhysicsConstants.MaxFloorGridEntriesPerTriangle * triangles.Length;
        int side = Math.Clamp((int)MathF.Ceiling(MathF.Sqrt(triangles.Length)), 1, PhysicsConstants.FloorGridMaxSide);
        var layout = new Layout(min, max, side);
        long entries = layout.CountEntries(triangles);
        if (entries > budget)
        {
            int fits = 1, fails = side;
            while (fails - fits > 1)
            {
                int mid = (fits + fails) / 2;
                if (new Layout(min, max, mid).CountEntries(triangles) <= budget)
                {
                    fits = mid;
                }
                else
                {
                    fails = mid;
                }
            }

            layout = new Layout(min, max, fits);
            entries = layout.CountEntries(triangles);
        }

        _layout = layout;
        int squares = layout.Columns * layout.Rows;
        var start = new int[squares + 1];
        for (int t = 0; t < triangles.Length; t++)
        {
            layout.Range(triangles[t], out int c0, out int c1, out int r0, out int r1);
            for (int r = r0; r <= r1; r++)
            {
                for (int c = c0; c <= c1; c++)
                {
                    start[(r * layout.Columns) + c + 1]++;
                }
            }
        }

        int sorted = 0;
        for (int s = 0; s < squares; s++)
        {
            sorted += start[s + 1] > PhysicsConstants.FloorGridLinearScanMax ? start[s + 1] : 0;
            start[s + 1] += start[s];
        }

        var zStart = sorted == 0 ? [] : new int[squares + 1];
        for (int s = 0; s < squares && sorted > 0; s++)
        {
            int count = start[s + 1] - start[s];
            zStart[s + 1] = zStart[s] + (count > PhysicsConstants.FloorGridLinearScanMax ? count : 0);
        }

        _start = start;
        _zStart = zStart;
        _items = new int[entries];
        _z = new ZRange[sorted];

        // Listing the triangles in order of lowest Z (when a run needs it) sorts every run at once.
        int[]? order = null;
        if (_z.Length > 0)
        {
            order = new int[triangles.Length];
            var keys = new float[triangles.Length];
            for (int t = 0; t < triangles.Length; t++)
            {
                order[t] = t;
                keys[t] = triangles[t].ZMin;
            }

            Array.Sort(keys, order);
        }

        int[] fill = start[..squares];
        for (int k = 0; k < triangles.Length; k++)
        {
            int t = order is null ? k : order[k];
            layout.Range(triangles[t], out int c0, out int c1, out int r0, out int r1);
            for (int r = r0; r <= r1; r++)
            {
                for (int c = c0; c <= c1; c++)
                {
                    _items[fill[(r * layout.Columns) + c]++] = t;
                }
            }
        }

        for (int s = 0; s < squares && sorted > 0; s++)
        {
            float highest = float.NegativeInfinity;
            for (int i = 0; i < zStart[s + 1] - zStart[s]; i++)
            {
                ref readonly FloorTriangle triangle = ref triangles[_items[start[s] + i]];
                highest = MathF.Max(highest, triangle.ZMax);
                _z[zStart[s] + i] = new ZRange(triangle.ZMin, highest);
            }
        }
    }

    /// <summary>Number of (square, triangle) entries: the grid's size, at most <see cref="PhysicsConstants.MaxFloorGridEntriesPerTriangle"/> × triangles.</summary>
    public int EntryCount => _items.Length;

    /// <summary>Number of squares (columns × rows).</summary>
    public int SquareCount => _layout.Columns * _layout.Rows;

    /// <summary>
    /// The floor under (x, y) nearest to <paramref name="referenceZ"/> (finite, or +∞ for the
    /// topmost); on an exact tie the higher: the same as <see cref="Keep"/> over every triangle.
    /// </summary>
    public bool TrySample(float x, float y, float referenceZ, out float z)
    {
        int square = _layout.Square(x, y);
        ReadOnlySpan<int> run = _items.AsSpan(_start[square], _start[square + 1] - _start[square]);
        FloorTriangle[] triangles = _triangles;
        bool found = false;
        float best = float.PositiveInfinity;
        z = 0f;
        if (run.Length <= PhysicsConstants.FloorGridLinearScanMax)
        {
            foreach (int t in run)
            {
                Keep(triangles[t], x, y, referenceZ, ref found, ref best, ref z);
            }

            return found;
        }

        // Sorted by lowest Z, with ZMaxUpTo the highest Z of the run so far. Float subtraction rounds
        // monotonically, so a bound on a triangle's Z bounds its rounded distance: a skipped triangle's
        // distance is provably greater than the best one's, or equal with a Z no higher.
        ReadOnlySpan<ZRange> ranges = _z.AsSpan(_zStart[square], run.Length);
        int first = FirstAtOrAbove(ranges, referenceZ);
        for (int i = first - 1; i >= 0; i--)
        {
            float below = ranges[i].ZMaxUpTo;
            float gap = referenceZ - below; // +∞ − finite is +∞: never more than best, compared by Z
            if (found && (gap > best || (gap == best && below <= z)))
            {
                break;
            }

            Keep(triangles[run[i]], x, y, referenceZ, ref found, ref best, ref z);
        }

        for (int i = first; i < run.Length; i++)
        {
            if (found)
            {
                float gap = ranges[i].ZMin - referenceZ;
                if (gap > best)
                {
                    break;
                }

                if (gap == best && ranges[i].ZMaxUpTo <= z)
                {
                    continue; // as near at best, and no higher: cannot win (a later one may)
                }
            }

            Keep(triangles[run[i]], x, y, referenceZ, ref found, ref best, ref z);
        }

        return found;
    }

    /// <summary>
    /// The floor selection, one triangle at a time: if <paramref name="triangle"/> contains (x, y) and
    /// its Z is nearer <paramref name="referenceZ"/> than the best so far (|Z − reference| in float), or
    /// as near and higher, it becomes the best. The result does not depend on the order of triangles.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Keep(in FloorTriangle triangle, float x, float y, float referenceZ, ref bool found, ref float best, ref float z)
    {
        if (!triangle.TrySample(x, y, out float candidate))
        {
            return;
        }

        float distance = MathF.Abs(candidate - referenceZ);
        if (!found || distance < best || (distance == best && candidate > z))
        {
            found = true;
            best = distance;
            z = candidate;
        }
    }

    /// <summary>Index of the first entry with ZMin ≥ <paramref name="referenceZ"/> (the run's length if none).</summary>
    private static int FirstAtOrAbove(ReadOnlySpan<ZRange> run, float referenceZ)
    {
        int lo = 0, hi = run.Length;
        while (lo < hi)
        {
            int mid = (lo + hi) >>> 1;
            if (run[mid].ZMin < referenceZ)
            {
                lo = mid + 1;
            }
            else
            {
                hi = mid;
            }
        }

        return lo;
    }

    /// <summary>
    /// The Z bounds of one entry of a sorted run: the triangle's lowest Z, and the highest Z of this
    /// and every earlier triangle of the run.
    /// </summary>
    private readonly struct ZRange(float zMin, float zMaxUpTo)
    {
        public readonly float ZMin = zMin;
        public readonly float ZMaxUpTo = zMaxUpTo;
    }

    /// <summary>The grid's squares: columns × rows over the bounds, about <c>side</c> along the longer axis.</summary>
    private readonly struct Layout
    {
        public readonly Vector2 Min;
        public readonly Vector2 InverseSize;
        public readonly int Columns;
        public readonly int Rows;

        public Layout(Vector2 min, Vector2 max, int side)
        {
            Vector2 extent = Vector2.Max(max - min, new Vector2(PhysicsConstants.FloorGridMinExtent));
            Columns = Math.Clamp((int)MathF.Ceiling(extent.X / MathF.Max(extent.X, extent.Y) * side), 1, PhysicsConstants.FloorGridMaxSide);
            Rows = Math.Clamp((int)MathF.Ceiling(extent.Y / MathF.Max(extent.X, extent.Y) * side), 1, PhysicsConstants.FloorGridMaxSide);
            Min = min;
            InverseSize = new Vector2(Columns / extent.X, Rows / extent.Y);
        }

        public int Square(float x, float y)
        {
            int column = Math.Clamp((int)((x - Min.X) * InverseSize.X), 0, Columns - 1);
            int row = Math.Clamp((int)((y - Min.Y) * InverseSize.Y), 0, Rows - 1);
            return (row * Columns) + column;
        }

        /// <summary>
        /// The squares a triangle's bounds overlap. Clamping the bounds into the grid keeps every
        /// triangle reachable from the squares a query can map to, even one rounding puts a hair outside.
        /// </summary>
        public void Range(in FloorTriangle triangle, out int c0, out int c1, out int r0, out int r1)
        {
            c0 = Math.Clamp((int)((triangle.Min.X - Min.X) * InverseSize.X), 0, Columns - 1);
            c1 = Math.Clamp((int)((triangle.Max.X - Min.X) * InverseSize.X), 0, Columns - 1);
            r0 = Math.Clamp((int)((triangle.Min.Y - Min.Y) * InverseSize.Y), 0, Rows - 1);
            r1 = Math.Clamp((int)((triangle.Max.Y - Min.Y) * InverseSize.Y), 0, Rows - 1);
        }

        public long CountEntries(FloorTriangle[] triangles)
        {
            long entries = 0;
            foreach (FloorTriangle triangle in triangles)
            {
                Range(triangle, out int c0, out int c1, out int r0, out int r1);
                entries += (long)(c1 - c0 + 1) * (r1 - r0 + 1);
            }

            return entries;
        }
    }
}
