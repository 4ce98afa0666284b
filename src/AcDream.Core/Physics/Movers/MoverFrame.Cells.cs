using System.Numerics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics.Movers;

/// <summary>
/// The outdoor cells (24 m, counted across the world) that have a mover filed in one of their 12 × 12 squares, and which
/// squares: a walk over a long box (a cast's stretch of path) looks once at each such cell it covers and then only at the
/// squares with a mover, not at every square.
/// </summary>
internal sealed partial class MoverFrame
{
    /// <summary>Squares along an outdoor cell's side (12).</summary>
    public const int SquaresPerCell = (int)(PhysicsConstants.CellSize / PhysicsConstants.MoverGridCell);

    /// <summary>Each cell with a mover filed, at the slot of its hash (linear probing; at least twice as many slots as movers).</summary>
    public FiledCell[] FiledCells = [];

    /// <summary>
    /// A cell with a mover filed: its key, x · 2³² + y (<see cref="long.MinValue"/>: an empty slot), and for each column c
    /// of its squares the rows with a mover filed (bit r: square (12·x + c, 12·y + r)), 16 bits a column, four columns a
    /// word; 32 bytes, the key and its rows read together.
    /// </summary>
    public struct FiledCell
    {
        public long Key;
        public ulong Rows0, Rows1, Rows2;

        public void Add(int c, int r)
        {
            ulong bit = 1UL << (((c & 3) * 16) + r);
            switch (c >> 2)
            {
                case 0: Rows0 |= bit; break;
                case 1: Rows1 |= bit; break;
                default: Rows2 |= bit; break;
            }
        }
    }

    /// <summary>Fills <see cref="FiledCells"/> from the squares the movers are filed in (<see cref="SquareX"/>, <see cref="SquareY"/>); <paramref name="size"/>, a power of two, at least twice the movers.</summary>
    public void FileCells(int size)
    {
        if (FiledCells.Length < size)
        {
            FiledCells = new FiledCell[size]; // grown only
        }

        FiledCell[] cells = FiledCells;
        Array.Fill(cells, new FiledCell { Key = long.MinValue });
        int mask = cells.Length - 1;
        for (int i = 0; i < Count; i++)
        {
            int cx = CellOf(SquareX[i]), cy = CellOf(SquareY[i]);
            long key = Key(cx, cy);
            int at = CellHash(cx, cy) & mask;
            while (cells[at].Key != long.MinValue && cells[at].Key != key)
            {
                at = (at + 1) & mask; // (at most half the slots are used: an empty one comes)
            }

            cells[at].Key = key;
            cells[at].Add(SquareX[i] - (cx * SquaresPerCell), SquareY[i] - (cy * SquaresPerCell));
        }
    }

    /// <summary>The slot of cell (cx, cy) in <see cref="FiledCells"/>; −1 when no mover is filed in it.</summary>
    public int FiledSlot(int cx, int cy)
    {
        FiledCell[] cells = FiledCells;
        int mask = cells.Length - 1;
        if (mask < 0)
        {
            return -1;
        }

        long key = Key(cx, cy);
        for (int at = CellHash(cx, cy) & mask; ; at = (at + 1) & mask)
        {
            if (cells[at].Key == key)
            {
                return at;
            }

            if (cells[at].Key == long.MinValue)
            {
                return -1;
            }
        }
    }

    /// <summary>The movers filed in the squares a box covers (the frame of landblock x, y), grown by the furthest reach, each once: by cell, column and row.</summary>
    public Filed FiledIn(int x, int y, Vector2 lo, Vector2 hi) => new(this, x, y, lo, hi);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static int CellOf(int square) => square >= 0 ? square / SquaresPerCell : -((-square + SquaresPerCell - 1) / SquaresPerCell);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static long Key(int cx, int cy) => ((long)cx << 32) | (uint)cy;

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static int CellHash(int cx, int cy) => (int)(((uint)cx * 0x9E3779B1u) ^ ((uint)cy * 0x85EBCA77u));

    /// <summary>
    /// The enumeration of <see cref="FiledIn"/>: cells with a mover filed, x then y; in each, its squares in the box with a
    /// mover filed, column by column west to east, each column's rows south to north (four columns' rows a word: a cell
    /// with none in the box is passed over in three tests).
    /// </summary>
    public ref struct Filed
    {
        private const float Beyond = 2f * PhysicsConstants.LandblockSize; // a box is clamped to its landblock and its neighbours

        private readonly MoverFrame _frame;
        private readonly int _sx0, _sx1, _sy0, _sy1, _cx1, _cy0, _cy1;
        private int _cx, _cy, _word, _colLo, _rowLo, _sx, _sy, _at, _end;
        private ulong _bits, _next, _last;

        public Filed(MoverFrame frame, int x, int y, Vector2 lo, Vector2 hi)
        {
            _frame = frame;
            float r = frame.Reach;
            _sx0 = Square(x, Math.Clamp(lo.X - r, -Beyond, Beyond));
            _sy0 = Square(y, Math.Clamp(lo.Y - r, -Beyond, Beyond));
            _sx1 = Square(x, Math.Clamp(hi.X + r, -Beyond, Beyond));
            _sy1 = Square(y, Math.Clamp(hi.Y + r, -Beyond, Beyond));
            (_cx, _cx1, _cy0, _cy1) = (CellOf(_sx0), CellOf(_sx1), CellOf(_sy0), CellOf(_sy1));
            (_cy, _word) = (_cy0 - 1, 3); // (no cell yet: the first MoveNext finds it)
        }

        public int Current { get; private set; }

        public bool MoveNext()
        {
            MoverFrame f = _frame;
            while (true)
            {
                while (_at < _end)
                {
                    int i = f.Order[_at++];
                    if (f.SquareX[i] == _sx && f.SquareY[i] == _sy)
                    {
                        Current = i;
                        return true; // (a mover of another square in the same bucket is that square's)
                    }
                }

                if (_bits != 0)
                {
                    int bit = BitOperations.TrailingZeroCount(_bits);
                    _bits &= _bits - 1;
                    (_sx, _sy) = (_colLo + (4 * _word) + (bit >> 4), _rowLo + (bit & 15));
                    int bucket = f.Bucket(_sx, _sy);
                    (_at, _end) = (f.Heads[bucket], f.Heads[bucket + 1]);
                }
                else if (++_word < 3)
                {
                    (_bits, _next, _last) = (_next, _last, 0);
                }
                else if (!NextCell())
                {
                    return false;
                }
            }
        }

        /// <summary>The columns c0..c1 of word <paramref name="w"/> (columns 4w..4w + 3): a 16-bit lane each.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static ulong Columns(int c0, int c1, int w) => Lanes(c1 + 1 - (4 * w)) & ~Lanes(c0 - (4 * w));

        /// <summary>The first <paramref name="n"/> lanes (clamped to 0–4) of a word.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static ulong Lanes(int n) => n <= 0 ? 0 : n >= 4 ? ulong.MaxValue : (1UL << (16 * n)) - 1;

        private bool NextCell()
        {
            while (true)
            {
                if (++_cy > _cy1)
                {
                    (_cy, _cx) = (_cy0, _cx + 1);
                    if (_cx > _cx1)
                    {
                        return false;
                    }
                }

                int slot = _frame.FiledSlot(_cx, _cy);
                if (slot < 0)
                {
                    continue; // no mover filed in this cell
                }

                (_colLo, _rowLo) = (_cx * SquaresPerCell, _cy * SquaresPerCell);
                int c0 = Math.Max(_sx0, _colLo) - _colLo, c1 = Math.Min(_sx1, _colLo + SquaresPerCell - 1) - _colLo;
                int r0 = Math.Max(_sy0, _rowLo) - _rowLo, r1 = Math.Min(_sy1, _rowLo + SquaresPerCell - 1) - _rowLo;
                ulong rows = (ulong)(((2u << r1) - 1) & ~((1u << r0) - 1)) * 0x0001_0001_0001_0001UL; // rows r0..r1 of each of four columns
                ref readonly FiledCell cell = ref _frame.FiledCells[slot];
                (_bits, _next, _last) = (cell.Rows0 & rows & Columns(c0, c1, 0), cell.Rows1 & rows & Columns(c0, c1, 1), cell.Rows2 & rows & Columns(c0, c1, 2));
                if ((_bits | _next | _last) == 0)
                {
                    continue; // none of its squares in the box has a mover filed
                }

                _word = 0;
                return true;
            }
        }
    }
}
