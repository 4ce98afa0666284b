using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics.World;

/// <summary>
/// The registered landblocks, one slot per landblock of the world. Readers (any number of threads
/// resolving) and one writer (registering and removing) share it without locks: an entry is
/// immutable and built completely before it is published by one reference write, so a reader sees
/// each landblock wholly as it was before a change or wholly after it, never half of one.
/// </summary>
internal sealed class LandblockRegistry
{
    private readonly LandblockEntry?[] _slots = new LandblockEntry?[PhysicsConstants.WorldSide * PhysicsConstants.WorldSide];
    private readonly uint[] _reachIn = new uint[PhysicsConstants.WorldSide * PhysicsConstants.WorldSide];
    private int _count;

    /// <summary>Number of registered landblocks.</summary>
    public int Count => Volatile.Read(ref _count);

    /// <summary>The landblock (lbX, lbY), or null when it is off the world or not registered.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public LandblockEntry? Get(int lbX, int lbY) =>
        CellIds.IsInWorld(lbX, lbY) ? Volatile.Read(ref _slots[CellIds.LandblockIndex(lbX, lbY)]) : null;

    /// <summary>
    /// How far the outdoor things of any landblock registered next to (<paramref name="lbX"/>, <paramref name="lbY"/>)
    /// since the engine was made reach into it (<paramref name="lbX"/>, <paramref name="lbY"/> in the world).
    /// </summary>
    /// <remarks>
    /// Only ever raised, and raised before the neighbour that needs it is published: read after a landblock's
    /// entry, it covers every version of its neighbours published until then, so a reader that skips a
    /// neighbour by it answers as with the neighbour it would have read.
    /// </remarks>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public SeamReach ReachInto(int lbX, int lbY) =>
        SeamReach.FromPacked(Volatile.Read(ref _reachIn[CellIds.LandblockIndex(lbX, lbY)]));

    /// <summary>Publishes <paramref name="entry"/>, replacing any entry of its landblock. One writer at a time.</summary>
    public void Set(LandblockEntry entry)
    {
        for (int dx = -1; dx <= 1; dx++)
        {
            for (int dy = -1; dy <= 1; dy++)
            {
                int x = entry.X + dx, y = entry.Y + dy;
                if ((dx | dy) != 0 && CellIds.IsInWorld(x, y))
                {
                    ref uint slot = ref _reachIn[CellIds.LandblockIndex(x, y)];
                    Volatile.Write(ref slot, SeamReach.Max(SeamReach.FromPacked(slot), SeamReach.Into(entry, dx, dy)).Packed);
                }
            }
        }

        LandblockEntry? previous = Interlocked.Exchange(ref _slots[CellIds.LandblockIndex(entry.X, entry.Y)], entry);
        if (previous is null)
        {
            Interlocked.Increment(ref _count);
        }
    }

    /// <summary>Removes landblock (lbX, lbY) if registered. One writer at a time.</summary>
    public void Remove(int lbX, int lbY)
    {
        if (CellIds.IsInWorld(lbX, lbY) && Interlocked.Exchange(ref _slots[CellIds.LandblockIndex(lbX, lbY)], null) is not null)
        {
            Interlocked.Decrement(ref _count);
        }
    }
}
