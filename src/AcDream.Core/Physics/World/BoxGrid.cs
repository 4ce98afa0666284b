using System.Numerics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics.World;

/// <summary>
/// A uniform grid over a set of boxes seen from above (landblock-local metres), built once: each square
/// lists the boxes overlapping it, and a query visits every box listed over the squares of its own box
/// exactly once, however many of them a box spans (it is visited at the first such square). Queries
/// outside the grid's bounds clamp to its border squares, which list everything beyond them, so no box is
/// missed; a query whose box misses the union of the boxes visits none. Immutable; queries allocate nothing.
/// </summary>
internal sealed class BoxGrid
{
    private readonly Vector2 _min;
    private readonly Vector2 _inverseSize;
    private readonly Vector2 _unionMin;
    private readonly Vector2 _unionMax;
    private readonly int _columns;
    private readonly int _rows;
    private readonly int[] _starts;
    private readonly int[] _items;
    private readonly Rect[] _rects;

    /// <summary>
    /// A grid over <paramref name="boxes"/> (an empty box, min &gt; max, is listed nowhere) spanning their
    /// union, with squares of about <paramref name="squareSize"/> metres, at most
    /// <see cref="PhysicsConstants.FloorGridMaxSide"/> per side. Null when no box is listed.
    /// </summary>
    public static BoxGrid? Build(ReadOnlySpan<(Vector2 Min, Vector2 Max)> boxes, float squareSize)
    {
        Vector2 min = new(float.MaxValue), max = new(float.MinValue);
        foreach ((Vector2 lo, Vector2 hi) in boxes)
        {
            if (lo.X <= hi.X && lo.Y <= hi.Y)
            {
                (min, max) = (Vector2.Min(min, lo), Vector2.Max(max, hi));
            }
        }

        if (!(min.X <= max.X))
        {
            return null;
        }

        Vector2 extent = Vector2.Max(max - min, new Vector2(squareSize));
        int columns = Math.Clamp((int)MathF.Ceiling(extent.X / squareSize), 1, PhysicsConstants.FloorGridMaxSide);
        int rows = Math.Clamp((int)MathF.Ceiling(extent.Y / squareSize), 1, PhysicsConstants.FloorGridMaxSide);
        return new BoxGrid(boxes, min, new Vector2(columns / extent.X, rows / extent.Y), columns, rows);
    }

    /// <summary>
    /// A grid of <paramref name="side"/> × <paramref name="side"/> squares of <paramref name="squareSize"/>
    /// metres from (0, 0) (a landblock's own squares), over <paramref name="boxes"/>; boxes beyond it are
    /// listed in its border squares.
    /// </summary>
    public static BoxGrid Fixed(ReadOnlySpan<(Vector2 Min, Vector2 Max)> boxes, int side, float squareSize) =>
        new(boxes, Vector2.Zero, new Vector2(1f / squareSize), side, side);

    private BoxGrid(ReadOnlySpan<(Vector2 Min, Vector2 Max)> boxes, Vector2 min, Vector2 inverseSize, int columns, int rows)
    {
        (_min, _inverseSize, _columns, _rows) = (min, inverseSize, columns, rows);
        (_unionMin, _unionMax) = (new Vector2(float.MaxValue), new Vector2(float.MinValue));
        _rects = new Rect[boxes.Length];
        _starts = new int[(columns * rows) + 1];
        for (int i = 0; i < boxes.Length; i++)
        {
            (Vector2 lo, Vector2 hi) = boxes[i];
            _rects[i] = Rect.Empty;
            if (lo.X <= hi.X && lo.Y <= hi.Y)
            {
                _rects[i] = new Rect(Column(lo.X), Column(hi.X), Row(lo.Y), Row(hi.Y));
                (_unionMin, _unionMax) = (Vector2.Min(_unionMin, lo), Vector2.Max(_unionMax, hi));
            }

            for (int c = _rects[i].C0; c <= _rects[i].C1; c++)
            {
                for (int r = _rects[i].R0; r <= _rects[i].R1; r++)
                {
                    _starts[(c * rows) + r + 1]++;
                }
            }
        }

        for (int k = 0; k < columns * rows; k++)
        {
            _starts[k + 1] += _starts[k];
        }

        _items = new int[_starts[columns * rows]];
        int[] next = _starts[..(columns * rows)];
        for (int i = 0; i < boxes.Length; i++)
        {
            for (int c = _rects[i].C0; c <= _rects[i].C1; c++)
            {
                for (int r = _rects[i].R0; r <= _rects[i].R1; r++)
                {
                    _items[next[(c * rows) + r]++] = i;
                }
            }
        }
    }

    /// <summary>Whether any box is listed over square (<paramref name="column"/>, <paramref name="row"/>).</summary>
    public bool Lists(int column, int row) => _starts[(column * _rows) + row] != _starts[(column * _rows) + row + 1];

    /// <summary>Whether any box is listed over a square of the box <paramref name="lo"/>–<paramref name="hi"/>: false is certain.</summary>
    public bool ListsAny(Vector2 lo, Vector2 hi)
    {
        if (!MeetsUnion(lo, hi))
        {
            return false;
        }

        int c0 = Column(lo.X), c1 = Column(hi.X), r0 = Row(lo.Y), r1 = Row(hi.Y);
        for (int c = c0; c <= c1; c++)
        {
            int k = (c * _rows) + r0;
            if (_starts[k] != _starts[k + (r1 - r0) + 1])
            {
                return true; // squares k .. k + (r1 − r0) of this column list at least one box
            }
        }

        return false;
    }

    /// <summary>The grid's column of an X (clamped to the grid).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public int Column(float x) => Index(x, _min.X, _inverseSize.X, _columns);

    /// <summary>The grid's row of a Y (clamped to the grid).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public int Row(float y) => Index(y, _min.Y, _inverseSize.Y, _rows);

    /// <summary>
    /// Every box listed over a square of the box <paramref name="lo"/>–<paramref name="hi"/>, each once (at the
    /// first such square), in order of the squares, column by column:
    /// <c>for (var c = grid.Near(lo, hi); c.MoveNext();) use(c.Current);</c>. A box is a candidate only: the
    /// caller tests it against its own question.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public Cursor Near(Vector2 lo, Vector2 hi) => MeetsUnion(lo, hi) ? new(this, Column(lo.X), Column(hi.X), Row(lo.Y), Row(hi.Y)) : default;

    /// <summary>Whether the box <paramref name="lo"/>–<paramref name="hi"/> meets the union of the listed boxes (false for a NaN box).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private bool MeetsUnion(Vector2 lo, Vector2 hi) =>
        lo.X <= _unionMax.X && hi.X >= _unionMin.X && lo.Y <= _unionMax.Y && hi.Y >= _unionMin.Y;

    /// <summary>The enumeration of <see cref="Near"/>: a square's run of items at a time, each box at its first square (the default visits none).</summary>
    public ref struct Cursor
    {
        private readonly ReadOnlySpan<int> _starts;
        private readonly ReadOnlySpan<int> _items;
        private readonly ReadOnlySpan<Rect> _rects;
        private readonly int _rows, _c0, _c1, _r0, _r1;
        private int _c, _r, _n, _end;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal Cursor(BoxGrid grid, int c0, int c1, int r0, int r1)
        {
            _starts = grid._starts;
            _items = grid._items;
            _rects = grid._rects;
            (_rows, _c0, _c1, _r0, _r1) = (grid._rows, c0, c1, r0, r1);
            (_c, _r) = (c0, r0);
            int k = (c0 * _rows) + r0;
            (_n, _end) = (_starts[k], _starts[k + 1]);
            Current = -1;
        }

        /// <summary>The box found: its index in the list the grid was built from.</summary>
        public int Current { get; private set; }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public bool MoveNext()
        {
            while (true)
            {
                while (_n < _end)
                {
                    int item = _items[_n++];
                    Rect rect = _rects[item];
                    if (_c == Math.Max(rect.C0, _c0) && _r == Math.Max(rect.R0, _r0))
                    {
                        Current = item; // seen here first: each box once per query
                        return true;
                    }
                }

                if (++_r > _r1)
                {
                    (_r, _c) = (_r0, _c + 1);
                    if (_c > _c1)
                    {
                        return false;
                    }
                }

                int k = (_c * _rows) + _r;
                (_n, _end) = (_starts[k], _starts[k + 1]);
            }
        }
    }

    /// <summary>The column (or row) of a coordinate, clamped to the grid; NaN-safe (a NaN coordinate maps to 0).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static int Index(float coordinate, float min, float inverseSize, int count)
    {
        float f = (coordinate - min) * inverseSize;
        return f >= count ? count - 1 : f > 0f ? (int)f : 0;
    }

    /// <summary>The squares a box covers: columns C0..C1, rows R0..R1.</summary>
    internal readonly record struct Rect(int C0, int C1, int R0, int R1)
    {
        public static Rect Empty => new(0, -1, 0, -1);
    }
}
