using System.Numerics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics;

/// <summary>
/// The walls around one body move: every cell and object whose walls may meet the box of the call, found
/// in the landblock's grids (<see cref="LandblockEntry.CellWalls"/>, <see cref="LandblockEntry.Objects"/>) and,
/// outdoors, in a neighbouring landblock whose reach the box meets across a seam (read through the call's
/// <see cref="Neighbourhood"/>, so each once). Indoors: the landblock's cells and the objects standing in
/// them. Outdoors: its buildings' cells and its outdoor objects. The sources are listed once, on the stack;
/// where more stand near than the list holds, every sweep asks the grids again over its own box instead, so
/// no wall is ever left out. All in the mover's landblock frame (landblock-local metres); allocation-free.
/// </summary>
/// <remarks>
/// Sweeps keep the nearest contact by a rule that does not depend on the order walls are met in
/// (<see cref="WallHit.Contact"/>), so the list and the grids give the same answers.
/// </remarks>
internal ref struct WallSet
{
    /// <summary>A source's landblock (<c>(dx + 1)·3 + (dy + 1)</c>, 4 for the mover's own) above this bit; below it, its index.</summary>
    private const int SlotShift = 24;

    /// <summary>Marks a source that is an outdoor object (else a cell).</summary>
    private const int ObjectBit = 1 << 23;

    private readonly ref Neighbourhood _lands;
    private readonly LandblockEntry _entry;
    private readonly bool _indoors;
    private readonly Span<int> _sources;
    private readonly int _count;

    /// <summary>
    /// The walls around a mover in landblock <paramref name="entry"/> (indoors: in one of its cells) whose
    /// sweeps stay in <paramref name="box"/>, listed in <paramref name="storage"/> (when they fit).
    /// </summary>
    public WallSet(ref Neighbourhood lands, LandblockEntry entry, bool indoors, Span<int> storage, in WallBox box)
    {
        _lands = ref lands;
        _entry = entry;
        _indoors = indoors;
        _count = -1;
        var list = new Lister(storage, box);
        Visit(ref lands, entry, indoors, box.Lo, box.Hi, ref list);
        if (!list.Full)
        {
            _sources = storage;
            _count = list.Count;
        }
    }

    /// <summary>
    /// Sweeps <paramref name="move"/> against every wall in its band whose bounds its box (the move grown by
    /// its radius and the contact tolerance) meets: the earliest contact before <c>hit.T</c>, and the deepest
    /// overlap at its start, into <paramref name="hit"/>.
    /// </summary>
    public readonly void Sweep(in BodyMove move, ref WallHit hit)
    {
        float grow = move.Radius + PhysicsConstants.ContactTolerance;
        Vector2 lo = Vector2.Min(move.P, move.P + move.D) - new Vector2(grow), hi = Vector2.Max(move.P, move.P + move.D) + new Vector2(grow);
        var sweep = new Sweeper(move, hit, lo, hi);
        if (_count < 0)
        {
            Visit(ref _lands, _entry, _indoors, lo, hi, ref sweep); // more sources than the list holds: the grids, over this sweep's box
        }
        else
        {
            for (int i = 0; i < _count; i++)
            {
                int source = _sources[i], slot = source >> SlotShift;
                LandblockEntry entry = slot == 4 ? _entry : _lands.Get(_entry.X + (slot / 3) - 1, _entry.Y + (slot % 3) - 1)!;
                sweep.Source(entry, slot, source & (ObjectBit - 1), (source & ObjectBit) != 0);
            }
        }

        hit = sweep.Hit;
    }

    /// <summary>
    /// Outdoors: whether any cell's or object's walls around a mover in <paramref name="entry"/> meet the box
    /// <paramref name="lo"/>–<paramref name="hi"/> (seen from above, at any height), in its landblock or across a
    /// seam: false is certain.
    /// </summary>
    public static bool AnyOutdoors(ref Neighbourhood lands, LandblockEntry entry, Vector2 lo, Vector2 hi)
    {
        var any = new Lister([], new WallBox(lo, hi, float.NegativeInfinity, float.PositiveInfinity));
        Visit(ref lands, entry, indoors: false, lo, hi, ref any);
        return any.Full;
    }

    /// <summary>The offset of a source landblock's frame from the mover's (slot as <see cref="SlotShift"/>).</summary>
    private static Vector2 Offset(int slot) =>
        new(((slot / 3) - 1) * PhysicsConstants.LandblockSize, ((slot % 3) - 1) * PhysicsConstants.LandblockSize);

    /// <summary>
    /// Hands every cell and object (of landblock <paramref name="entry"/> and, outdoors, of a neighbour whose reach
    /// meets the box) whose walls may meet the box <paramref name="lo"/>–<paramref name="hi"/> to
    /// <paramref name="visitor"/>, until it stops.
    /// </summary>
    private static void Visit<T>(ref Neighbourhood lands, LandblockEntry entry, bool indoors, Vector2 lo, Vector2 hi, scoped ref T visitor)
        where T : ISourceVisitor, allows ref struct
    {
        if (!Visit(entry, 4, indoors, lo, hi, ref visitor) || indoors)
        {
            return;
        }

        SeamNeighbours across = Neighbourhood.Across(ref lands, entry, lo, hi);
        while (across.MoveNext())
        {
            if (!Visit(across.Current, across.Slot, indoors, lo, hi, ref visitor))
            {
                return;
            }
        }
    }

    /// <summary>One landblock's sources for the box (in the mover's frame); false when the visitor stopped.</summary>
    private static bool Visit<T>(LandblockEntry entry, int slot, bool indoors, Vector2 lo, Vector2 hi, scoped ref T visitor)
        where T : ISourceVisitor, allows ref struct
    {
        Vector2 offset = Offset(slot);
        lo -= offset;
        hi -= offset;
        if ((indoors ? entry.CellWalls : entry.OutdoorCellWalls) is BoxGrid cellGrid)
        {
            var cells = new GridVisit<T>(entry, slot, false, visitor);
            bool going = cellGrid.Query(lo, hi, ref cells);
            visitor = cells.Visitor;
            if (!going)
            {
                return false;
            }
        }

        if (indoors || entry.OutdoorObjects.Length == 0)
        {
            return true;
        }

        var objects = new GridVisit<T>(entry, slot, true, visitor);
        bool more = entry.Objects.Query(lo, hi, ref objects);
        visitor = objects.Visitor;
        return more;
    }

    /// <summary>A grid's box, handed on as a source (a cell, or an outdoor object) of its landblock; the visitor is carried by value and read back.</summary>
    private ref struct GridVisit<T>(LandblockEntry entry, int slot, bool objects, T visitor) : IBoxVisitor
        where T : ISourceVisitor, allows ref struct
    {
        public T Visitor = visitor;

        public bool Visit(int item) => Visitor.Source(entry, slot, item, objects);
    }

    /// <summary>Lists the sources whose walls meet the box and band in a span; stops (full) when one more does not fit.</summary>
    private ref struct Lister(Span<int> storage, WallBox box) : ISourceVisitor
    {
        private readonly Span<int> _storage = storage;

        public int Count;

        public bool Full;

        public bool Source(LandblockEntry entry, int slot, int index, bool isObject)
        {
            if (!Meets(entry, slot, index, isObject, in box))
            {
                return true;
            }

            if (Count == _storage.Length)
            {
                Full = true;
                return false;
            }

            _storage[Count++] = (slot << SlotShift) | (isObject ? ObjectBit : 0) | index;
            return true;
        }
    }

    /// <summary>Whether a source's walls (or a cell's objects' walls) meet the box and band (the mover's frame).</summary>
    private static bool Meets(LandblockEntry entry, int slot, int index, bool isObject, in WallBox box)
    {
        Vector2 offset = Offset(slot);
        Vector2 lo = box.Lo - offset, hi = box.Hi - offset;
        if (isObject)
        {
            ref readonly ObjectBox b = ref entry.ObjectBoxes[index];
            return b.WallMin.X <= hi.X && b.WallMax.X >= lo.X && b.WallMin.Y <= hi.Y && b.WallMax.Y >= lo.Y && b.ZMax > box.ZLow && b.ZMin < box.ZHigh;
        }

        CellSurface cell = entry.Cells[index];
        bool meets = Meets(cell.Walls, lo, hi, in box);
        foreach (ObjectSurface o in cell.Objects)
        {
            meets |= Meets(o.Walls, lo, hi, in box);
        }

        return meets;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static bool Meets(CellWalls walls, Vector2 lo, Vector2 hi, in WallBox box) =>
        walls.Polygons.Length > 0 && walls.Min.X <= hi.X && walls.Max.X >= lo.X && walls.Min.Y <= hi.Y && walls.Max.Y >= lo.Y
        && walls.ZMax > box.ZLow && walls.ZMin < box.ZHigh;

    /// <summary>Sweeps a body move against the walls of each source.</summary>
    private struct Sweeper(BodyMove move, WallHit hit, Vector2 lo, Vector2 hi) : ISourceVisitor
    {
        private readonly BodyMove _move = move;

        public WallHit Hit = hit;

        public bool Source(LandblockEntry entry, int slot, int index, bool isObject)
        {
            Vector2 offset = Offset(slot);
            Vector2 boxLo = lo - offset, boxHi = hi - offset;
            if (isObject)
            {
                ref readonly ObjectBox b = ref entry.ObjectBoxes[index];
                if (!(b.WallMin.X > boxHi.X || b.WallMax.X < boxLo.X || b.WallMin.Y > boxHi.Y || b.WallMax.Y < boxLo.Y))
                {
                    BodySweep.SweepWalls(entry.OutdoorObjects[index].Walls, offset, boxLo, boxHi, in _move, ref Hit);
                }

                return true;
            }

            CellSurface cell = entry.Cells[index];
            BodySweep.SweepWalls(cell.Walls, offset, boxLo, boxHi, in _move, ref Hit);
            foreach (ObjectSurface o in cell.Objects)
            {
                BodySweep.SweepWalls(o.Walls, offset, boxLo, boxHi, in _move, ref Hit);
            }

            return true;
        }
    }

}

/// <summary>A box seen from above and a height band, landblock-local metres: where a call's sweeps stay.</summary>
internal readonly record struct WallBox(Vector2 Lo, Vector2 Hi, float ZLow, float ZHigh);

/// <summary>What <see cref="WallSet"/> hands each cell or outdoor object whose walls may meet a box.</summary>
internal interface ISourceVisitor
{
    /// <summary>
    /// Handles cell <paramref name="index"/> (or outdoor object, <paramref name="isObject"/>) of
    /// <paramref name="entry"/>, whose frame is the mover's landblock's offset by the slot's landblock; false stops the visit.
    /// </summary>
    bool Source(LandblockEntry entry, int slot, int index, bool isObject);
}
