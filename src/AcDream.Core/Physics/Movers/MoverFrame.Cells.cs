using System.Numerics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics;

/// <summary>
/// The outdoor cells (24 m, counted across the world) that have a mover filed in one of their 12 × 12 squares, and which
/// squares: a walk over a long box (a cast's stretch of path) looks once at each such cell it covers and then only at the
/// squares with a mover, not at every square.
/// </summary>
internal sealed partial class MoverFrame
{
    /// <summary>Squares along an outdoor cell's side (12).</summary>
    public const int SquaresPerCell = (int)(PhysicsConstants.CellSize / PhysicsConstants.MoverGridCell);

    /// <summary>Each cell with a mover filed: x · 2³² + y at the slot of its hash (linear probing; at least twice as many slots as movers); <see cref="long.MinValue"/>: empty.</summary>
    public long[] FiledCells = [];

    /// <summary><see cref="SquaresPerCell"/> per slot of <see cref="FiledCells"/>, one per column c of the cell: bit r set when square (12·x + c, 12·y + r) has a mover filed.</summary>
    public ushort[] FiledRows = [];

    /// <summary>Fills <see cref="FiledCells"/> and <see cref="FiledRows"/> from the squares the movers are filed in (<see cref="SquareX"/>, <see cref="SquareY"/>); <paramref name="size"/>, a power of two, at least twice the movers.</summary>
    public void FileCells(int size)
    {
        if (FiledCells.Length < size)
        {
            (FiledCells, FiledRows) = (new long[size], new ushort[size * SquaresPerCell]); // grown only
        }

        Array.Fill(FiledCells, long.MinValue);
        int mask = FiledCells.Length - 1;
        for (int i = 0; i < Count; i++)
        {
            int cx = CellOf(SquareX[i]), cy = CellOf(SquareY[i]);
            long key = Key(cx, cy);
            int at = CellHash(cx, cy) & mask;
            while (FiledCells[at] != long.MinValue && FiledCells[at] != key)
            {
                at = (at + 1) & mask; // (at most half the slots are used: an empty one comes)
            }

            if (FiledCells[at] != key)
            {
                FiledCells[at] = key;
                Array.Clear(FiledRows, at * SquaresPerCell, SquaresPerCell); // (a slot's rows are cleared when it is taken)
            }

            FiledRows[(at * SquaresPerCell) + SquareX[i] - (cx * SquaresPerCell)] |= (ushort)(1 << (SquareY[i] - (cy * SquaresPerCell)));
        }
    }

    /// <summary>The slot of cell (cx, cy) in <see cref="FiledCells"/>; −1 when no mover is filed in it.</summary>
    public int FiledSlot(int cx, int cy)
    {
        long[] cells = FiledCells;
        int mask = cells.Length - 1;
        if (mask < 0)
        {
            return -1;
        }

        long key = Key(cx, cy);
        for (int at = CellHash(cx, cy) & mask; ; at = (at + 1) & mask)
        {
            if (cells[at] == key)
            {
                return at;
            }

            if (cells[at] == long.MinValue)
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

    /// <summary>The enumeration of <see cref="FiledIn"/>: cells with a mover filed, x then y; in each, its columns in the box, west to east, and their rows with one, south to north.</summary>
    public ref struct Filed
    {
        private const float Beyond = 2f * PhysicsConstants.LandblockSize; // a box is clamped to its landblock and its neighbours

        private readonly MoverFrame _frame;
        private readonly int _sx0, _sx1, _sy0, _sy1, _cx1, _cy0, _cy1;
        private int _cx, _cy, _slot, _sx, _colLo, _colEnd, _rowLo, _sy, _at, _end;
        private uint _rows, _bits;

        public Filed(MoverFrame frame, int x, int y, Vector2 lo, Vector2 hi)
        {
            _frame = frame;
            float r = frame.Reach;
            _sx0 = Square(x, Math.Clamp(lo.X - r, -Beyond, Beyond));
            _sy0 = Square(y, Math.Clamp(lo.Y - r, -Beyond, Beyond));
            _sx1 = Square(x, Math.Clamp(hi.X + r, -Beyond, Beyond));
            _sy1 = Square(y, Math.Clamp(hi.Y + r, -Beyond, Beyond));
            (_cx, _cx1, _cy0, _cy1) = (CellOf(_sx0), CellOf(_sx1), CellOf(_sy0), CellOf(_sy1));
            _cy = _cy0 - 1; // (no cell yet: the first MoveNext finds it)
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
                    _sy = _rowLo + BitOperations.TrailingZeroCount(_bits);
                    _bits &= _bits - 1;
                    int bucket = f.Bucket(_sx, _sy);
                    (_at, _end) = (f.Heads[bucket], f.Heads[bucket + 1]);
                }
                else if (_sx < _colEnd)
                {
                    _sx++;
                    _bits = f.FiledRows[(_slot * SquaresPerCell) + _sx - _colLo] & _rows;
                }
                else if (!NextCell())
                {
                    return false;
                }
            }
        }

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

                (_slot, _colLo, _rowLo) = (slot, _cx * SquaresPerCell, _cy * SquaresPerCell);
                int r0 = Math.Max(_sy0, _rowLo) - _rowLo, r1 = Math.Min(_sy1, _rowLo + SquaresPerCell - 1) - _rowLo;
                _rows = ((2u << r1) - 1) & ~((1u << r0) - 1); // rows r0..r1
                (_sx, _colEnd) = (Math.Max(_sx0, _colLo), Math.Min(_sx1, _colLo + SquaresPerCell - 1));
                _bits = _frame.FiledRows[(slot * SquaresPerCell) + _sx - _colLo] & _rows;
                return true;
            }
        }
    }
}
