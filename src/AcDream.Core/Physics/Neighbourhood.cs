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
/// It keeps the first <see cref="Capacity"/> landblocks a call reads (a 3 × 3 block: any move of up
/// to a landblock's length); a call reading more (a swept move longer than that) reads the further
/// ones afresh each time.
/// </remarks>
internal struct Neighbourhood
{
    /// <summary>How many landblocks one call keeps.</summary>
    public const int Capacity = 9;

    private readonly LandblockRegistry _registry;
    private Entries _entries;
    private Keys _keys;
    private int _count;

    public Neighbourhood(LandblockRegistry registry) => _registry = registry;

    /// <summary>Landblock (<paramref name="x"/>, <paramref name="y"/>), as this call first read it; null when not registered or off the world.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public LandblockEntry? Get(int x, int y)
    {
        int key = (x << 16) | (y & 0xFFFF);
        for (int i = 0; i < _count; i++)
        {
            if (_keys[i] == key)
            {
                return _entries[i];
            }
        }

        return Read(x, y, key);
    }

    /// <summary>
    /// The landblocks next to <paramref name="entry"/> whose outdoor objects or building walls
    /// (<see cref="LandblockEntry.OutdoorMin"/>–<see cref="LandblockEntry.OutdoorMax"/>) meet the box
    /// <paramref name="lo"/>–<paramref name="hi"/> (<paramref name="entry"/>'s frame), each with the offset of its
    /// frame from <paramref name="entry"/>'s. A box farther than <see cref="PhysicsConstants.MaxSeamReach"/> from
    /// every seam reads none.
    /// </summary>
    public static SeamNeighbours Across(ref Neighbourhood lands, LandblockEntry entry, Vector2 lo, Vector2 hi) => new(ref lands, entry, lo, hi);

    /// <summary>The first read of a landblock in this call: kept while there is room.</summary>
    private LandblockEntry? Read(int x, int y, int key)
    {
        LandblockEntry? entry = _registry.Get(x, y);
        if (_count < Capacity)
        {
            _keys[_count] = key;
            _entries[_count++] = entry;
        }

        return entry;
    }

    [InlineArray(Capacity)]
    private struct Entries
    {
        private LandblockEntry? _first;
    }

    [InlineArray(Capacity)]
    private struct Keys
    {
        private int _first;
    }
}

/// <summary>The enumeration of <see cref="Neighbourhood.Across"/>: <c>while (n.MoveNext()) { n.Current, n.Offset }</c>.</summary>
internal ref struct SeamNeighbours
{
    private readonly ref Neighbourhood _lands;
    private readonly LandblockEntry _entry;
    private readonly Vector2 _lo;
    private readonly Vector2 _hi;
    private int _next;

    public SeamNeighbours(ref Neighbourhood lands, LandblockEntry entry, Vector2 lo, Vector2 hi)
    {
        const float size = PhysicsConstants.LandblockSize, reach = PhysicsConstants.MaxSeamReach;
        _lands = ref lands;
        (_entry, _lo, _hi) = (entry, lo, hi);
        _next = lo.X >= reach && lo.Y >= reach && hi.X <= size - reach && hi.Y <= size - reach ? 9 : 0; // far from every seam: none
        Current = null!;
    }

    /// <summary>The neighbour found.</summary>
    public LandblockEntry Current { get; private set; }

    /// <summary>Its frame's offset from the entry's, metres: a point of its frame is this much more in the entry's.</summary>
    public Vector2 Offset { get; private set; }

    public bool MoveNext()
    {
        const float size = PhysicsConstants.LandblockSize, reach = PhysicsConstants.MaxSeamReach;
        while (_next < 9)
        {
            int dx = (_next / 3) - 1, dy = (_next % 3) - 1;
            _next++;
            var offset = new Vector2(dx * size, dy * size);
            if ((dx | dy) == 0
                || _lo.X > offset.X + size + reach || _hi.X < offset.X - reach || _lo.Y > offset.Y + size + reach || _hi.Y < offset.Y - reach
                || _lands.Get(_entry.X + dx, _entry.Y + dy) is not LandblockEntry neighbour
                || !neighbour.OutdoorsOverlaps(_lo - offset, _hi - offset))
            {
                continue;
            }

            (Current, Offset) = (neighbour, offset);
            return true;
        }

        return false;
    }
}
