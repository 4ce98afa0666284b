using System.Numerics;
using System.Runtime.Intrinsics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics;

/// <summary>
/// The walls around one body move, found once per call and listed on the stack. Indoors: the walls of the
/// mover's cell and of every cell reached from it through portals whose openings meet the call's box (what
/// the game's cell-by-cell collision sees), with the objects standing in them. Outdoors: those of the
/// landblock's buildings' cells and outdoor objects whose bounds meet the box and band (its grids:
/// <see cref="LandblockEntry.OutdoorCellWalls"/>, <see cref="LandblockEntry.Objects"/>), and of a neighbouring
/// landblock whose reach the box meets across a seam (read through the call's <see cref="Neighbourhood"/>, so
/// each once). Where more stand near than the list holds, every sweep asks the grids again over its own box
/// instead (indoors: every cell of the mover's building there, a superset), so no wall is ever left out.
/// All in the mover's landblock frame (landblock-local metres); allocation-free.
/// </summary>
/// <remarks>
/// Sweeps keep the nearest contact by a rule that does not depend on the order walls are met in
/// (<see cref="WallHit.Contact"/>), so the order of the list does not change an answer.
/// </remarks>
internal ref struct WallSet
{
    /// <summary>A listed source's landblock (its slot: see <see cref="Own"/>) above this bit; below it, its index.</summary>
    private const int SlotShift = 24;

    /// <summary>Marks a listed source that is an outdoor object (else a cell).</summary>
    private const int ObjectBit = 1 << 23;

    private const int MoverBit = 1 << 22;

    private readonly ref Neighbourhood _lands;
    private readonly LandblockEntry _entry;
    private readonly int _cell;
    private readonly Span<int> _listed;
    private readonly int _count;
    private readonly float _moverDrop;

    /// <summary>
    /// The walls around a mover in landblock <paramref name="entry"/> (in its cell <paramref name="cellIndex"/>,
    /// or outdoors: −1) whose sweeps stay in <paramref name="box"/>, listed in <paramref name="storage"/> (when they fit).
    /// </summary>
    public WallSet(ref Neighbourhood lands, LandblockEntry entry, int cellIndex, Span<int> storage, in WallBox box, float moverDrop = 0f)
    {
        _moverDrop = moverDrop;
        _lands = ref lands;
        _entry = entry;
        _cell = cellIndex;
        var list = new Lister(storage);
        bool listed = cellIndex >= 0
            ? Reach(entry, cellIndex, in box, ref list) && (lands.Movers is null || Movers(ref lands, entry, box with { ZLow = box.ZLow - moverDrop }, ref list))
            : Collect(ref lands, entry, -1, in box, ref list, moverDrop);
        _count = listed ? list.Count : -1;
        _listed = storage;
    }

    /// <summary>
    /// Indoors: the mover's cell and every cell reached from it through a portal whose bounds meet the box,
    /// breadth first, into <paramref name="list"/> (which keeps them once); false when they do not fit.
    /// </summary>
    private static bool Reach(LandblockEntry entry, int cellIndex, in WallBox box, ref Lister list)
    {
        if (!list.Add((Own << SlotShift) | cellIndex))
        {
            return false;
        }

        Vector128<float> query = WallExtent.Query(box.Lo, box.Hi);
        for (int i = 0; i < list.Count; i++)
        {
            int cell = list[i] & (MoverBit - 1);
            int[] targets = entry.PortalTargets[cell];
            ReadOnlySpan<Vector128<float>> extents = entry.Cells[cell].PortalExtents.AsSpan(0, targets.Length);
            for (int k = 0; k < extents.Length; k++)
            {
                if (targets[k] >= 0 && Vector128.LessThanOrEqualAll(extents[k], query)
                    && !list.Contains((Own << SlotShift) | targets[k]) && !list.Add((Own << SlotShift) | targets[k]))
                {
                    return false;
                }
            }
        }

        return true;
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
        var sweep = new Sweeper(ref _lands, _entry, in move, ref hit, lo, hi, _moverDrop);
        if (_count < 0)
        {
            // More sources than the list holds: the grids, over this sweep's box and band.
            Collect(ref _lands, _entry, _cell, new WallBox(lo, hi, move.ZLow, move.ZHigh), ref sweep, _moverDrop);
            return;
        }

        for (int i = 0; i < _count; i++)
        {
            sweep.Add(_listed[i]);
        }
    }

    /// <summary>
    /// Lowers <paramref name="hit"/> to the lowest surface over the disc of <paramref name="rise"/> above its top: every
    /// wall polygon, cylinder and floor (seen from below) of the cells and objects around it (<see cref="Overhead"/>).
    /// </summary>
    public readonly void Rise(in BodyRise rise, ref CeilingHit hit)
    {
        var riser = new Riser(ref _lands, _entry, in rise, ref hit);
        Read(ref riser, in rise, rise.Top, hit.Z);
        if (_cell < 0)
        {
            // Outdoors, objects with floors and no wall there (a slab) are not listed by their walls: their undersides.
            var r = new Vector2(rise.Radius);
            Vector2 lo = rise.Centre - r, hi = rise.Centre + r;
            FloorsOnly(_entry, Vector2.Zero, lo, hi, in rise, ref hit);
            if (_lands.ReachInto(_entry).Meets(lo, hi))
            {
                SeamNeighbours across = Neighbourhood.Across(ref _lands, _entry, lo, hi);
                while (across.MoveNext())
                {
                    FloorsOnly(across.Current, across.Offset, lo, hi, in rise, ref hit);
                }
            }
        }
    }

    /// <summary>
    /// Raises <paramref name="hit"/> to the highest steep face (too steep to stand on, not to land on) over the disc of
    /// <paramref name="fall"/> from its top (the feet) down to <c>hit.Z</c>, among the cells' and objects' walls around it
    /// (<see cref="Overhead.Steep"/>).
    /// </summary>
    public readonly void Steep(in BodyRise fall, ref CeilingHit hit)
    {
        var riser = new Riser(ref _lands, _entry, in fall, ref hit, steep: true);
        Read(ref riser, in fall, hit.Z, fall.Top);
    }

    /// <summary>Hands <paramref name="riser"/> the listed sources, or, where more stand near than the list holds, those the grids give over the disc and band <paramref name="zLow"/>–<paramref name="zHigh"/>.</summary>
    private readonly void Read(ref Riser riser, in BodyRise disc, float zLow, float zHigh)
    {
        if (_count < 0)
        {
            var r = new Vector2(disc.Radius);
            Collect(ref _lands, _entry, _cell, new WallBox(disc.Centre - r, disc.Centre + r, zLow, zHigh), ref riser);
            return;
        }

        for (int i = 0; i < _count; i++)
        {
            riser.Add(_listed[i]);
        }
    }

    /// <summary>The floors (seen from below) of <paramref name="entry"/>'s outdoor objects over the box whose walls do not reach it (those were listed with their walls).</summary>
    private static void FloorsOnly(LandblockEntry entry, Vector2 offset, Vector2 lo, Vector2 hi, in BodyRise rise, ref CeilingHit hit)
    {
        if (entry.OutdoorObjects.Length == 0)
        {
            return;
        }

        (lo, hi) = (lo - offset, hi - offset);
        for (BoxGrid.Cursor near = entry.Objects.Near(lo, hi); near.MoveNext();)
        {
            ref readonly ObjectBox b = ref entry.ObjectBoxes[near.Current];
            bool walls = b.WallMin.X <= hi.X && b.WallMax.X >= lo.X && b.WallMin.Y <= hi.Y && b.WallMax.Y >= lo.Y;
            if (!walls && b.FloorMin.X <= hi.X && b.FloorMax.X >= lo.X && b.FloorMin.Y <= hi.Y && b.FloorMax.Y >= lo.Y && b.ZMax > rise.Top)
            {
                ObjectSurface o = entry.OutdoorObjects[near.Current];
                hit.Current = WallSource.Of(o);
                Overhead.Floors(o.Floors, offset, in rise, ref hit);
            }
        }
    }

    /// <summary>
    /// Outdoors: whether any cell's or object's walls around a mover in <paramref name="entry"/> meet the box
    /// <paramref name="lo"/>–<paramref name="hi"/> (seen from above, at any height), in its landblock or across a
    /// seam: false is certain.
    /// </summary>
    public static bool AnyOutdoors(ref Neighbourhood lands, LandblockEntry entry, Vector2 lo, Vector2 hi)
    {
        var none = new Lister([]);
        var box = new WallBox(lo, hi, float.NegativeInfinity, float.PositiveInfinity);
        return !(Collect(entry, Own, -1, in box, ref none)
            && (!lands.ReachInto(entry).Meets(box.Lo, box.Hi) || CollectAcross(ref lands, entry, in box, ref none)));
    }

    /// <summary>
    /// Whether the body's sweep <paramref name="move"/> (the frame of <paramref name="entry"/>) touches a solid mover, or
    /// starts overlapping one: movers near a move but clear of its sweep leave it on open ground.
    /// </summary>
    public static bool TouchesMover(ref Neighbourhood lands, LandblockEntry entry, in BodyMove move, float moverDrop)
    {
        if (lands.Movers is not MoverFrame movers)
        {
            return false;
        }

        float grow = move.Radius + PhysicsConstants.ContactTolerance;
        Vector2 lo = Vector2.Min(move.P, move.P + move.D) - new Vector2(grow), hi = Vector2.Max(move.P, move.P + move.D) + new Vector2(grow);
        return MoverTouch(ref lands, movers, entry, move with { ZLow = move.ZLow - moverDrop }, lo, hi);
    }

    /// <summary>
    /// Whether the move's disc passes every one of <paramref name="walls"/>, all upright cylinders, by more than 1 mm (the
    /// least distance from its path to each axis, seen from above): then its sweep cannot touch them. False for walls
    /// that are not all cylinders (they are swept).
    /// </summary>
    private static bool Clears(CellWalls walls, Vector2 offset, in BodyMove move)
    {
        Vector2 p = move.P - offset, d = move.D;
        float length2 = d.LengthSquared();
        foreach (ref readonly WallPolygon w in walls.Polygons.AsSpan())
        {
            float t = length2 > 0f ? Math.Clamp(Vector2.Dot(w.A - p, d) / length2, 0f, 1f) : 0f;
            float clear = move.Radius + w.Radius + 0.001f;
            if (w.Radius <= 0f || Vector2.DistanceSquared(p + (d * t), w.A) <= clear * clear)
            {
                return false;
            }
        }

        return true;
    }

    [MethodImpl(MethodImplOptions.NoInlining)] // out of the common path: only with movers near
    private static bool MoverTouch(ref Neighbourhood lands, MoverFrame movers, LandblockEntry entry, in BodyMove move, Vector2 lo, Vector2 hi)
    {
        var hit = WallHit.None;
        for (Neighbourhood.MoverCursor near = lands.MoversNear(entry.X, entry.Y, new WallBox(lo, hi, move.ZLow, move.ZHigh)); near.MoveNext();)
        {
            CellWalls walls = movers.Walls[near.Current];
            if (lands.Blocks(near.Current) && !Clears(walls, near.Offset, in move))
            {
                MoverSolid.Sweep(walls, near.Offset, lo - near.Offset, hi - near.Offset, in move, ref hit);
                if (hit.T < 1f || hit.Depth > 0f)
                {
                    return true;
                }
            }
        }

        return false;
    }

    /// <summary>
    /// Hands every source (a cell, with its objects, or an outdoor object) whose walls meet <paramref name="box"/>
    /// to <paramref name="sink"/>: indoors (the mover in cell <paramref name="cellIndex"/>), the cells of its
    /// building; outdoors (−1), the buildings' cells and outdoor objects of <paramref name="entry"/> and of a
    /// neighbour whose reach meets the box. False when the sink stopped taking them.
    /// </summary>
    private static bool Collect<T>(ref Neighbourhood lands, LandblockEntry entry, int cellIndex, in WallBox box, ref T sink, float moverDrop = 0f)
        where T : ISourceSink, allows ref struct
    {
        if (!Collect(entry, Own, cellIndex, in box, ref sink))
        {
            return false;
        }

        return (cellIndex >= 0 || !lands.ReachInto(entry).Meets(box.Lo, box.Hi) || CollectAcross(ref lands, entry, in box, ref sink))
            && (lands.Movers is null || Movers(ref lands, entry, box with { ZLow = box.ZLow - moverDrop }, ref sink));
    }

    /// <summary>Whether a solid mover's walls meet the box and band (a shortcut that finds no wall of the world there must still sweep it).</summary>
    public static bool AnyMover(ref Neighbourhood lands, LandblockEntry entry, in WallBox box)
    {
        if (lands.Movers is null)
        {
            return false;
        }

        var none = new Lister([]);
        return !Movers(ref lands, entry, in box, ref none);
    }

    /// <summary>The solid movers (to this call's mover) whose walls meet the box and band, from every landblock around.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // out of the common path: only with movers committed
    private static bool Movers<T>(ref Neighbourhood lands, LandblockEntry entry, in WallBox box, ref T sink)
        where T : ISourceSink, allows ref struct
    {
        if (lands.Movers is null)
        {
            return true;
        }

        for (Neighbourhood.MoverCursor near = lands.MoversNear(entry.X, entry.Y, box); near.MoveNext();)
        {
            if (lands.Blocks(near.Current) && !sink.Add((near.Slot << SlotShift) | MoverBit | near.Current))
            {
                return false;
            }
        }

        return true;
    }

    /// <summary>The sources of the neighbours of <paramref name="entry"/> whose reach meets the box; false when the sink stopped.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // out of the common path: only within a neighbour's reach
    private static bool CollectAcross<T>(ref Neighbourhood lands, LandblockEntry entry, in WallBox box, ref T sink)
        where T : ISourceSink, allows ref struct
    {
        SeamNeighbours across = Neighbourhood.Across(ref lands, entry, box.Lo, box.Hi);
        while (across.MoveNext())
        {
            if (!Collect(across.Current, across.Slot, -1, in box, ref sink))
            {
                return false;
            }
        }

        return true;
    }

    /// <summary>One landblock's sources (in slot <paramref name="slot"/>) whose walls meet the box; false when the sink stopped.</summary>
    private static bool Collect<T>(LandblockEntry entry, int slot, int cellIndex, in WallBox box, ref T sink)
        where T : ISourceSink, allows ref struct
    {
        Vector2 offset = Offset(slot);
        Vector2 lo = box.Lo - offset, hi = box.Hi - offset;
        bool indoors = cellIndex >= 0;
        if ((indoors ? entry.CellWalls : entry.OutdoorCellWalls) is BoxGrid cells)
        {
            WallBounds[] bounds = entry.CellWallBounds;
            int group = indoors ? entry.CellGroups[cellIndex] : -1;
            for (BoxGrid.Cursor near = cells.Near(lo, hi); near.MoveNext();)
            {
                int c = near.Current;
                if ((!indoors || entry.CellGroups[c] == group) && bounds[c].Meets(in box, offset) && !sink.Add((slot << SlotShift) | c))
                {
                    return false;
                }
            }
        }

        if (indoors || entry.OutdoorObjects.Length == 0)
        {
            return true;
        }

        ObjectBox[] objects = entry.ObjectBoxes;
        for (BoxGrid.Cursor near = entry.Objects.Near(lo, hi); near.MoveNext();)
        {
            ref readonly ObjectBox b = ref objects[near.Current];
            if (b.WallMin.X <= hi.X && b.WallMax.X >= lo.X && b.WallMin.Y <= hi.Y && b.WallMax.Y >= lo.Y && b.ZMax > box.ZLow && b.ZMin < box.ZHigh
                && !sink.Add((slot << SlotShift) | ObjectBit | near.Current))
            {
                return false;
            }
        }

        return true;
    }

    /// <summary>The slot of the mover's own landblock: (dx + 1)·3 + (dy + 1) for the one at (dx, dy) from it.</summary>
    private const int Own = 4;

    /// <summary>The offset of a slot's landblock frame from the mover's.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static Vector2 Offset(int slot) => slot == Own
        ? default
        : new(((slot / 3) - 1) * PhysicsConstants.LandblockSize, ((slot % 3) - 1) * PhysicsConstants.LandblockSize);

    /// <summary>What the sources found are handed to, one encoded source at a time (slot, object bit, index).</summary>
    private interface ISourceSink
    {
        /// <summary>Takes a source; false to stop.</summary>
        bool Add(int source);
    }

    /// <summary>Lists the sources in a span; stops when one more does not fit.</summary>
    private ref struct Lister(Span<int> storage) : ISourceSink
    {
        private readonly Span<int> _storage = storage;

        public int Count;

        public readonly int this[int i] => _storage[i];

        public readonly bool Contains(int source) => _storage[..Count].Contains(source);

        public bool Add(int source)
        {
            if (Count == _storage.Length)
            {
                return false;
            }

            _storage[Count++] = source;
            return true;
        }
    }

    /// <summary>Sweeps a body move against each source's walls (a cell's with its objects', or an outdoor object's).</summary>
    private ref struct Sweeper(ref Neighbourhood lands, LandblockEntry entry, in BodyMove move, ref WallHit hit, Vector2 lo, Vector2 hi, float moverDrop) : ISourceSink
    {
        private readonly ref Neighbourhood _lands = ref lands;
        private readonly ref readonly BodyMove _move = ref move;
        private readonly ref WallHit _hit = ref hit;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public bool Add(int source)
        {
            int slot = source >> SlotShift, index = source & (MoverBit - 1);
            Vector2 offset = Offset(slot);
            Vector2 boxLo = lo - offset, boxHi = hi - offset;
            if ((source & MoverBit) != 0)
            {
                MoverFrame movers = _lands.Movers!;
                _hit.Current = new WallSource(SurfaceKind.Mover, movers.Ids[index]);
                MoverSolid.Sweep(movers.Walls[index], offset, boxLo, boxHi, _move with { ZLow = _move.ZLow - moverDrop }, ref _hit);
                return true;
            }

            LandblockEntry of = slot == Own ? entry : _lands.Get(entry.X + (slot / 3) - 1, entry.Y + (slot % 3) - 1)!;
            if ((source & ObjectBit) != 0)
            {
                ObjectSurface outdoors = of.OutdoorObjects[index];
                _hit.Current = WallSource.Of(outdoors);
                BodySweep.SweepWalls(outdoors.Walls, offset, boxLo, boxHi, in _move, ref _hit);
                return true;
            }

            CellSurface cell = of.Cells[index];
            _hit.Current = new WallSource(SurfaceKind.CellWall, cell.CellId);
            ulong near = cell.OpenFloor is OpenFloor open ? open.WallsNear(boxLo, boxHi) : ulong.MaxValue;
            BodySweep.SweepWalls(cell.Walls, near, offset, new WallBox(boxLo, boxHi, _move.ZLow, _move.ZHigh), in _move, ref _hit);
            foreach (ObjectSurface o in cell.Objects)
            {
                _hit.Current = WallSource.Of(o);
                BodySweep.SweepWalls(o.Walls, offset, boxLo, boxHi, in _move, ref _hit);
            }

            return true;
        }
    }

    /// <summary>Reads each source's surfaces overhead for a rising body (a cell's walls and floors with its objects', or an outdoor object's); or, <c>steep</c>, the steep faces under a falling one.</summary>
    private ref struct Riser(ref Neighbourhood lands, LandblockEntry entry, in BodyRise rise, ref CeilingHit hit, bool steep = false) : ISourceSink
    {
        private readonly ref Neighbourhood _lands = ref lands;
        private readonly ref readonly BodyRise _rise = ref rise;
        private readonly ref CeilingHit _hit = ref hit;

        public bool Add(int source)
        {
            int slot = source >> SlotShift, index = source & (MoverBit - 1);
            Vector2 offset = Offset(slot);
            if ((source & MoverBit) != 0)
            {
                MoverFrame movers = _lands.Movers!;
                _hit.Current = new WallSource(SurfaceKind.Mover, movers.Ids[index]);
                if (steep)
                {
                    Overhead.Tops(movers.Walls[index], offset, in _rise, ref _hit);
                }
                else
                {
                    Overhead.Walls(movers.Walls[index], offset, in _rise, ref _hit);
                }

                return true;
            }

            LandblockEntry of = slot == Own ? entry : _lands.Get(entry.X + (slot / 3) - 1, entry.Y + (slot % 3) - 1)!;
            if ((source & ObjectBit) != 0)
            {
                Read(of.OutdoorObjects[index], offset);
                return true;
            }

            CellSurface cell = of.Cells[index];
            _hit.Current = new WallSource(SurfaceKind.CellWall, cell.CellId);
            if (steep)
            {
                Overhead.Steep(cell.Walls, offset, in _rise, ref _hit);
            }
            else
            {
                Overhead.Walls(cell.Walls, offset, in _rise, ref _hit);
                if (cell.FloorZMax > _rise.Top)
                {
                    Overhead.Floors(cell.Floors, offset, in _rise, ref _hit); // (a cell's floors all below the head are no ceiling)
                }
            }

            foreach (ObjectSurface o in cell.Objects)
            {
                Read(o, offset);
            }

            return true;
        }

        private readonly void Read(ObjectSurface o, Vector2 offset)
        {
            _hit.Current = WallSource.Of(o);
            if (steep)
            {
                Overhead.Steep(o.Walls, offset, in _rise, ref _hit);
                return;
            }

            Overhead.Walls(o.Walls, offset, in _rise, ref _hit);
            if (o.BoundsMax.Z > _rise.Top)
            {
                Overhead.Floors(o.Floors, offset, in _rise, ref _hit);
            }
        }
    }
}

/// <summary>A box seen from above and a height band, landblock-local metres: where a call's sweeps stay.</summary>
internal readonly record struct WallBox(Vector2 Lo, Vector2 Hi, float ZLow, float ZHigh);
