using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.Movers;

namespace AcDream.Core.Physics.World;

/// <summary>
/// The landblocks one <c>Resolve</c> (or host query) reads, each read from the registry at most once:
/// every later question about the same landblock in the same call gets the entry read first, so the
/// call sees each landblock whole, in one version, even while a writer replaces it. Lives on the
/// caller's stack for one call and is passed by reference; reading allocates nothing.
/// </summary>
/// <remarks>
/// It keeps the 3 × 3 landblocks around the first one the call reads (any move of up to a landblock's
/// length stays among them); a call reading one farther away (a swept move longer than that) reads it
/// afresh each time.
/// </remarks>
internal partial struct Neighbourhood
{
    private readonly LandblockRegistry _registry;

    /// <summary>The first landblock the call read (its centre), at <see cref="_centreX"/>, <see cref="_centreY"/>: most calls read no other.</summary>
    private LandblockEntry? _centre;
    private Entries _entries;
    private int _centreX;
    private int _centreY;

    /// <summary>Bit (dx + 1)·3 + (dy + 1) set once landblock (centre + (dx, dy)) is read (the centre's, bit 4, with the centre).</summary>
    private int _read;

    public Neighbourhood(LandblockRegistry registry) => (_registry, _centreX) = (registry, int.MinValue); // (no centre yet: no landblock has that X)

    /// <summary>
    /// Holds the committed movers for this call, for the mover <paramref name="self"/> (0: not a mover) starting at
    /// <paramref name="start"/> in <paramref name="cellId"/>, whose queries all lie within <paramref name="reach"/> of its
    /// start (metres, seen from above): when no mover's walls reach into that box the call reads no movers at all (and
    /// holds none); else the movers met there (not itself) are listed once, and every query of the call reads that list.
    /// </summary>
    /// <returns>Whether the call holds movers (and must <see cref="Release"/> them).</returns>
    [MethodImpl(MethodImplOptions.NoInlining)] // out of the common path: only with movers committed
    public bool Meet(MoverRegistry movers, in WorldFrame frame, Vector3 start, uint cellId, float reach, uint self)
    {
        if (!HoldMovers(movers, in frame, start, cellId, reach, self))
        {
            return false;
        }

        _call!.Gather();
        return true;
    }

    /// <summary>
    /// Whether the caller asked what the move met: then the kind and id of the wall, shell, cylinder or mover that stops
    /// or slides the move are recorded in <see cref="MetKind"/> and <see cref="MetId"/> (<c>MoveQuery.Meet</c>;
    /// the answer gives the normal); otherwise nothing is written.
    /// </summary>
    public bool Reporting;

    /// <summary>What stopped or slid the call's move, when <see cref="Reporting"/>.</summary>
    public SurfaceKind MetKind;

    /// <summary>The id of <see cref="MetKind"/>'s surface.</summary>
    public uint MetId;

    /// <summary>Lets go of the movers held for this call (<see cref="Meet"/>).</summary>
    public readonly void Release() => _call?.Release();

    /// <summary>The movers this call reads (this thread's record, set by <see cref="Meet"/>), or null: none near.</summary>
    private MoverCall? _call;

    /// <summary>The committed movers this call reads, one whole state; null when none is near it.</summary>
    public readonly MoverFrame? Movers => _call?.Frame;

    /// <summary>Whether mover <paramref name="index"/> of <see cref="Movers"/> stops this call's move (it is met, and solid to the mover).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly bool Blocks(int index) => MoverState.Blocks(in _call!.Self, in _call.Frame!.States[index]);

    /// <summary>The movers met by this call (not itself) whose walls meet <paramref name="box"/> (the frame of landblock x, y), each once.</summary>
    public readonly MoverCursor MoversNear(int x, int y, WallBox box) => new(_call!, x, y, box);

    /// <summary>
    /// What one call reads of the movers: the state it holds, who is moving, and the movers met near its start (up to
    /// <see cref="Capacity"/>; more, and each query asks the state's squares over the call's box). One per thread, reused
    /// by each call of that thread that has movers near (a call is never inside another on one thread).
    /// </summary>
    internal sealed class MoverCall
    {
        public const int Capacity = 24;

        [ThreadStatic]
        private static MoverCall? _ofThisThread;

        public readonly int[] Near = new int[Capacity];
        public MoverFrame? Frame;
        public uint SelfId;
        public MoverState Self;
        public int Count;
        public int X, Y;
        public Vector2 Lo, Hi;

        /// <summary>How many movers this thread's casts have looked at in the squares they are filed in (<see cref="MoversAlong"/>), all told: what a cast pays in movers (the tests read it).</summary>
        public long Examined;

        public static MoverCall OfThisThread() => _ofThisThread ??= new MoverCall(); // (once per thread)

        /// <summary>Sets the call's state, who is moving and the box about its start (frame of landblock x, y), listing none yet (<see cref="Count"/> −1).</summary>
        public void Set(MoverFrame held, int x, int y, Vector2 lo, Vector2 hi, uint self) =>
            (Frame, SelfId, Self, X, Y, Lo, Hi, Count) = (held, self, self == 0 ? MoverState.Unregistered : held.StateOf(self), x, y, lo, hi, -1);

        /// <summary>Lists the movers met in the call's box (up to <see cref="Capacity"/>).</summary>
        public void Gather()
        {
            (MoverFrame held, int x, int y, Vector2 lo, Vector2 hi, uint self) = (Frame!, X, Y, Lo, Hi, SelfId);
            int n = 0;
            for (MoverFrame.Near near = held.Around(x, y, lo, hi); near.MoveNext();)
            {
                int j = near.Current;
                CellWalls w = held.Walls[j];
                if (held.Ids[j] == self || !MoverState.Meets(in held.States[j]) || !held.TryOffset(j, x, y, out Vector2 offset, out _)
                    || !new WallBounds(w.Min, w.Max, float.NegativeInfinity, float.PositiveInfinity).Meets(new WallBox(lo, hi, 0f, 0f), offset))
                {
                    continue; // itself, not met, or not reaching into the call's box
                }

                if (n == Capacity)
                {
                    n = -1; // more than the list holds: each query asks the squares
                    break;
                }

                Near[n++] = j;
            }

            Count = n;
        }

        public void Release()
        {
            Physics.MoverRegistry.Release(Frame);
            Frame = null;
        }
    }

    /// <summary>The movers of <see cref="MoversNear"/>: each with its walls' offset from the query's frame and its 3 × 3 slot there.</summary>
    internal ref struct MoverCursor
    {
        private readonly MoverCall _call;
        private readonly WallBox _box;
        private readonly int _x, _y;
        private MoverFrame.Near _grid;
        private int _i;

        public MoverCursor(MoverCall call, int x, int y, WallBox box)
        {
            (_call, _x, _y, _box, _i) = (call, x, y, box, 0);
            _grid = call.Count < 0 ? call.Frame!.Around(call.X, call.Y, call.Lo, call.Hi) : default;
        }

        public int Current { get; private set; }

        public Vector2 Offset { get; private set; }

        public int Slot { get; private set; }

        public bool MoveNext()
        {
            MoverFrame movers = _call.Frame!;
            while (true)
            {
                int j;
                if (_call.Count >= 0)
                {
                    if (_i == _call.Count)
                    {
                        return false;
                    }

                    j = _call.Near[_i++];
                }
                else
                {
                    if (!_grid.MoveNext())
                    {
                        return false;
                    }

                    j = _grid.Current;
                    if (movers.Ids[j] == _call.SelfId || !MoverState.Meets(in movers.States[j]))
                    {
                        continue;
                    }
                }

                CellWalls w = movers.Walls[j];
                if (movers.TryOffset(j, _x, _y, out Vector2 offset, out int slot) && new WallBounds(w.Min, w.Max, w.ZMin, w.ZMax).Meets(in _box, offset))
                {
                    (Current, Offset, Slot) = (j, offset, slot);
                    return true;
                }
            }
        }
    }

    /// <summary>Landblock (<paramref name="x"/>, <paramref name="y"/>) as this call first read it (null: not loaded, or off the world).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public LandblockEntry? Get(int x, int y)
    {
        if (x == _centreX && y == _centreY)
        {
            return _centre;
        }

        if (_centreX == int.MinValue)
        {
            (_centreX, _centreY, _read) = (x, y, 1 << 4); // the first landblock read is the centre
            return _centre = _registry.Get(x, y);
        }

        return Read(x, y);
    }

    /// <summary><see cref="Get"/> of a landblock other than the centre: the 3 × 3 around the centre are kept.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // out of the common path: a call that reads only its centre pays two compares
    private LandblockEntry? Read(int x, int y)
    {
        uint dx = (uint)(x - _centreX + 1), dy = (uint)(y - _centreY + 1);
        if (dx > 2 || dy > 2)
        {
            return _registry.Get(x, y); // beyond the 3 × 3 block: not kept
        }

        int slot = (int)((dx * 3) + dy);
        if ((_read & (1 << slot)) == 0)
        {
            _entries[slot] = _registry.Get(x, y);
            _read |= 1 << slot;
        }

        return _entries[slot];
    }

    /// <summary>How far the things of the neighbours of <paramref name="entry"/> (read by this call) may reach into it (<see cref="LandblockRegistry.ReachInto"/>).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly SeamReach ReachInto(LandblockEntry entry) => _registry.ReachInto(entry.X, entry.Y);

    /// <summary>
    /// The landblocks next to <paramref name="entry"/> whose outdoor objects or building walls
    /// (<see cref="LandblockEntry.OutdoorMin"/>–<see cref="LandblockEntry.OutdoorMax"/>) meet the box
    /// <paramref name="lo"/>–<paramref name="hi"/> (<paramref name="entry"/>'s frame), each with the offset of its
    /// frame from <paramref name="entry"/>'s. A box out of every neighbour's reach
    /// (<see cref="ReachInto"/>) reads none.
    /// </summary>
    public static SeamNeighbours Across(ref Neighbourhood lands, LandblockEntry entry, Vector2 lo, Vector2 hi) => new(ref lands, entry, lo, hi);

    [InlineArray(9)]
    private struct Entries
    {
        private LandblockEntry? _first;
    }
}

/// <summary>The enumeration of <see cref="Neighbourhood.Across"/>: <c>while (n.MoveNext()) { n.Current, n.Offset }</c>.</summary>
internal ref struct SeamNeighbours
{
    private readonly ref Neighbourhood _lands;
    private readonly LandblockEntry _entry;
    private readonly Vector2 _lo;
    private readonly Vector2 _hi;
    private readonly int _x1, _y0, _y1;
    private int _dx, _dy;

    public SeamNeighbours(ref Neighbourhood lands, LandblockEntry entry, Vector2 lo, Vector2 hi)
    {
        const float size = PhysicsConstants.LandblockSize;
        _lands = ref lands;
        (_entry, _lo, _hi) = (entry, lo, hi);

        // The neighbours whose reach into the entry the box meets: dx from −1 or 0 to _x1, dy from _y0 to _y1.
        SeamReach reach = lands.ReachInto(entry);
        int x0 = lo.X < reach.West ? -1 : 0;
        (_x1, _y0, _y1) = (hi.X > size - reach.East ? 1 : 0, lo.Y < reach.South ? -1 : 0, hi.Y > size - reach.North ? 1 : 0);
        (_dx, _dy) = (x0, _y0 - 1);
        if (x0 == 0 && _x1 == 0 && _y0 == 0 && _y1 == 0)
        {
            _dx = 2; // far from every seam: none
        }

        Current = null!;
    }

    /// <summary>The neighbour found.</summary>
    public LandblockEntry Current { get; private set; }

    /// <summary>Its frame's offset from the entry's, metres: a point of its frame is this much more in the entry's.</summary>
    public readonly Vector2 Offset => new(_dx * PhysicsConstants.LandblockSize, _dy * PhysicsConstants.LandblockSize);

    /// <summary>Where it lies: (dx + 1)·3 + (dy + 1) for the neighbour at (dx, dy) from the entry.</summary>
    public readonly int Slot => ((_dx + 1) * 3) + _dy + 1;

    public bool MoveNext()
    {
        while (true)
        {
            if (++_dy > _y1)
            {
                (_dx, _dy) = (_dx + 1, _y0);
                if (_dx > _x1)
                {
                    return false;
                }
            }

            if ((_dx | _dy) == 0 || _lands.Get(_entry.X + _dx, _entry.Y + _dy) is not LandblockEntry neighbour)
            {
                continue;
            }

            Vector2 offset = Offset;
            if (neighbour.OutdoorsOverlaps(_lo - offset, _hi - offset))
            {
                Current = neighbour;
                return true;
            }
        }
    }
}
