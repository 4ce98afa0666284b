using System.Numerics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics;

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
internal struct Neighbourhood
{
    private readonly LandblockRegistry _registry;
    private Entries _entries;
    private int _centreX;
    private int _centreY;

    /// <summary>Bit (dx + 1)·3 + (dy + 1) set once landblock (centre + (dx, dy)) is read; bit 9 once the centre is set.</summary>
    private int _read;

    public Neighbourhood(LandblockRegistry registry) => _registry = registry;

    /// <summary>The committed movers this call holds (null: none), and who is moving: its id (0: not a mover) and state.</summary>
    public Neighbourhood(LandblockRegistry registry, MoverFrame? movers, uint self)
    {
        _registry = registry;
        Movers = movers;
        if (movers is not null && self != 0)
        {
            (SelfId, Self) = (self, movers.StateOf(self));
        }
    }

    /// <summary>The committed movers this call reads, one whole state; null when there are none.</summary>
    public readonly MoverFrame? Movers;

    /// <summary>The id of the mover that moves (skipped), or 0.</summary>
    public readonly uint SelfId;

    /// <summary>The state of the mover that moves (the rules of who blocks whom read it).</summary>
    public readonly MoverState Self;

    /// <summary>Whether mover <paramref name="index"/> of <see cref="Movers"/> stops this call's move (not the mover itself, and solid to it).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public readonly bool Blocks(int index) =>
        Movers!.Ids[index] != SelfId && MoverState.Blocks(in Self, in Movers.States[index]);

    /// <summary>Landblock (<paramref name="x"/>, <paramref name="y"/>), as this call first read it; null when not registered or off the world.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public LandblockEntry? Get(int x, int y)
    {
        if (_read == 0)
        {
            (_centreX, _centreY, _read) = (x, y, 1 << 9); // the first landblock read is the centre
        }

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
