using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Surfaces;

namespace AcDream.Core.Physics.Movers;

/// <summary>
/// One whole state of the registered movers, as a call reads it: each mover's id, state, landblock and walls placed in
/// that landblock's frame, filed by origin in squares of <see cref="PhysicsConstants.MoverGridCell"/> (a hash of the
/// global square, counting-sorted). Written only by <see cref="MoverRegistry.Commit"/> while no reader holds it
/// (<see cref="Readers"/>), then published; a call holds the one it found at its start to its end.
/// </summary>
internal sealed partial class MoverFrame
{
    /// <summary>How many calls hold this frame; the writer rewrites a frame only when none does and it is not current.</summary>
    public int Readers;

    /// <summary>Odd while the writer rewrites this frame, even otherwise, one more at each change: a call that reads without holding (<see cref="Occupied"/>) checks it did not change.</summary>
    public int Sequence;

    /// <summary>The number of the commit that wrote this frame (<see cref="MoverRegistry.CommitNumber"/>).</summary>
    public long Commit;

    public int Count;
    public uint[] Ids = [];
    public MoverState[] States = [];
    public int[] LandblockX = [];
    public int[] LandblockY = [];

    /// <summary>The global square each mover's origin is filed in (a bucket may hold other squares' movers too).</summary>
    public int[] SquareX = [];
    public int[] SquareY = [];
    public CellWalls[] Walls = [];
    public MoverShape?[] Shapes = [];
    public long[] Versions = [];

    /// <summary>The bucket of each square (hash, masked) starts at <c>Heads[bucket]</c> of <see cref="Order"/> and ends at <c>Heads[bucket + 1]</c>.</summary>
    public int[] Heads = [];
    public int[] Order = [];
    public int Mask;

    /// <summary>Each mover's index + 1 at the slot of its id's hash (linear probing, the same size as <see cref="Heads"/> less one); 0: empty.</summary>
    public int[] ById = [];

    /// <summary>The furthest any mover's walls reach from its origin, seen from above, metres.</summary>
    public float Reach;

    /// <summary>
    /// Which outdoor cells (24 m squares, bit 8·x + y) of a landblock any mover's walls reach into: the landblock's index
    /// + 1 in <see cref="Landblocks"/> at the slot of its hash (linear probing; 0: empty), its bits in <see cref="Occupancy"/>.
    /// </summary>
    public int[] Landblocks = [];
    public ulong[] Occupancy = [];

    public const int SquaresPerLandblock = (int)(PhysicsConstants.LandblockSize / PhysicsConstants.MoverGridCell);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static int Square(int landblock, float local) => (landblock * SquaresPerLandblock) + (int)MathF.Floor(local / PhysicsConstants.MoverGridCell);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public int Bucket(int x, int y) => (int)(((uint)x * 0x9E3779B1u) ^ ((uint)y * 0x85EBCA77u)) & Mask;

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public int IdSlot(uint id) => (int)(id * 0x9E3779B1u) & Mask;

    /// <summary>The committed state of mover <paramref name="id"/>; an unregistered one's is an object's.</summary>
    public MoverState StateOf(uint id)
    {
        for (int at = IdSlot(id); ById[at] != 0; at = (at + 1) & Mask)
        {
            if (Ids[ById[at] - 1] == id)
            {
                return States[ById[at] - 1];
            }
        }

        return MoverState.Unregistered;
    }

    /// <summary>
    /// Whether any mover's walls may reach into the box <paramref name="lo"/>..<paramref name="hi"/> (the frame of landblock
    /// x, y; it may cross into the neighbours): one look at the outdoor cells it covers.
    /// </summary>
    public bool Occupied(int x, int y, Vector2 lo, Vector2 hi)
    {
        const float size = PhysicsConstants.LandblockSize;
        (int[] keys, ulong[] bits) = (Landblocks, Occupancy); // each read once: a call may read a frame it does not hold
        if (keys.Length != bits.Length)
        {
            return true; // (torn: being rewritten)
        }

        if (lo.X >= 0f && lo.Y >= 0f && hi.X <= size && hi.Y <= size)
        {
            return (Cells(lo, hi) & OccupancyOf(keys, bits, x, y)) != 0; // within its landblock: one look
        }

        for (int dx = lo.X < 0f ? -1 : 0; dx <= (hi.X > size ? 1 : 0); dx++)
        {
            for (int dy = lo.Y < 0f ? -1 : 0; dy <= (hi.Y > size ? 1 : 0); dy++)
            {
                var offset = new Vector2(dx * size, dy * size);
                if ((Cells(lo - offset, hi - offset) & OccupancyOf(keys, bits, x + dx, y + dy)) != 0)
                {
                    return true;
                }
            }
        }

        return false;
    }

    /// <summary>The bits of the outdoor cells of one landblock a box (its frame) covers.</summary>
    public static ulong Cells(Vector2 lo, Vector2 hi)
    {
        const float cell = PhysicsConstants.LandblockSize / PhysicsConstants.CellsPerSide;
        if (hi.X < 0f || hi.Y < 0f || lo.X > PhysicsConstants.LandblockSize || lo.Y > PhysicsConstants.LandblockSize)
        {
            return 0;
        }

        int x0 = Math.Clamp((int)(lo.X / cell), 0, 7), x1 = Math.Clamp((int)(hi.X / cell), 0, 7);
        int y0 = Math.Clamp((int)(lo.Y / cell), 0, 7), y1 = Math.Clamp((int)(hi.Y / cell), 0, 7);
        ulong column = ((2UL << y1) - 1) & ~((1UL << y0) - 1); // bits y0..y1
        ulong bits = 0;
        for (int cx = x0; cx <= x1; cx++)
        {
            bits |= column << (8 * cx);
        }

        return bits;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static int LandblockSlot(int key, int length) => (int)((uint)key * 0x9E3779B1u) & (length - 1);

    private static ulong OccupancyOf(int[] keys, ulong[] bits, int x, int y)
    {
        int key = CellIds.LandblockIndex(Math.Clamp(x, 0, PhysicsConstants.MaxLandblockIndex), Math.Clamp(y, 0, PhysicsConstants.MaxLandblockIndex)) + 1;
        for (int at = LandblockSlot(key, keys.Length), n = 0; keys[at] != 0 && n < keys.Length; at = (at + 1) & (keys.Length - 1), n++)
        {
            if (keys[at] == key)
            {
                return bits[at];
            }
        }

        return 0;
    }

    /// <summary>The movers whose walls' bounds may meet the box <paramref name="lo"/>..<paramref name="hi"/> (the frame of landblock x, y), each once or more.</summary>
    public Near Around(int x, int y, Vector2 lo, Vector2 hi) => new(this, x, y, lo, hi);

    /// <summary>A mover's walls' offset from the frame of landblock x, y: its landblock's origin there (−1, 0 or +1 landblocks), or null beyond.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public bool TryOffset(int index, int x, int y, out Vector2 offset, out int slot)
    {
        int dx = LandblockX[index] - x, dy = LandblockY[index] - y;
        offset = new Vector2(dx * PhysicsConstants.LandblockSize, dy * PhysicsConstants.LandblockSize);
        slot = ((dx + 1) * 3) + dy + 1;
        return (uint)(dx + 1) <= 2 && (uint)(dy + 1) <= 2;
    }

    /// <summary>
    /// The movers filed in the squares a box covers, grown by the furthest reach, each once; every mover once when the box
    /// covers more squares than there are movers.
    /// </summary>
    public ref struct Near
    {
        private const float Beyond = 2f * PhysicsConstants.LandblockSize; // a box is clamped to its landblock and its neighbours

        private readonly MoverFrame _frame;
        private readonly int _y0, _x1, _y1;
        private int _x, _y, _at, _end;
        private readonly bool _all;

        public Near(MoverFrame frame, int x, int y, Vector2 lo, Vector2 hi)
        {
            _frame = frame;
            float r = frame.Reach;
            _x = Square(x, Math.Clamp(lo.X - r, -Beyond, Beyond));
            _y0 = Square(y, Math.Clamp(lo.Y - r, -Beyond, Beyond));
            _x1 = Square(x, Math.Clamp(hi.X + r, -Beyond, Beyond));
            _y1 = Square(y, Math.Clamp(hi.Y + r, -Beyond, Beyond));
            _y = _y0 - 1;
            (_at, _end, _all) = (0, 0, (long)(_x1 - _x + 1) * (_y1 - _y0 + 1) > frame.Count);
            if (_all)
            {
                _end = frame.Count; // every mover, in filing order
            }
        }

        public int Current { get; private set; }

        public bool MoveNext()
        {
            while (true)
            {
                while (_at < _end)
                {
                    int i = _frame.Order[_at++];
                    if (_all || (_frame.SquareX[i] == _x && _frame.SquareY[i] == _y))
                    {
                        Current = i;
                        return true; // (a mover of another square in the same bucket is that square's)
                    }
                }

                if (_all || !NextSquare())
                {
                    return false;
                }
            }
        }

        private bool NextSquare()
        {
            if (++_y > _y1)
            {
                (_y, _x) = (_y0, _x + 1);
            }

            if (_x > _x1)
            {
                return false;
            }

            int bucket = _frame.Bucket(_x, _y);
            (_at, _end) = (_frame.Heads[bucket], _frame.Heads[bucket + 1]);
            return true;
        }
    }
}
