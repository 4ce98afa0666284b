using System.Numerics;
using System.Runtime.Intrinsics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.Movers;

namespace AcDream.Core.Physics.Body;

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
internal ref partial struct WallSet
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
            ? Reach(entry, cellIndex, in box, ref list) && (/* Stryker disable once Logical : with movers, a list that says it does not fit sends each sweep to the grids, a superset */ lands.Movers is null || Movers(ref lands, entry, box with { ZLow = box.ZLow - moverDrop }, ref list))
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
        list.Add((Own << SlotShift) | cellIndex); // (the list is empty here, and holds at least one)
        Vector128<float> query = WallExtent.Query(box.Lo, box.Hi);
        for (int i = 0; i < list.Count; i++)
        {
            int cell = list[i] & (MoverBit - 1);
            int[] targets = entry.PortalTargets[cell];
            ReadOnlySpan<Vector128<float>> extents = entry.Cells[cell].PortalExtents.AsSpan(0, targets.Length);
            for (int k = 0; k < extents.Length; k++)
            {
                if (targets[k] < 0 || !Vector128.LessThanOrEqualAll(extents[k], query))
                {
                    continue;
                }

                int key = (Own << SlotShift) | targets[k];
                // Stryker disable once Boolean,Logical : listing a cell twice, or saying the list does not fit (each sweep then asks the grids), gives a superset
                if (!list.Contains(key) && !list.Add(key))
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
        // Stryker disable once Equality,Statement : with nothing listed the grids give nothing in this box (it lies in the list's), and the loop below runs no turn for −1
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
        // Stryker disable once Equality,Statement : with nothing listed the grids give nothing over the disc (it lies in the list's box), and the loop below runs no turn for −1
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
        // Stryker disable once Statement,Block : with no outdoor objects the grid lists none
        if (entry.OutdoorObjects.Length == 0)
        {
            return;
        }

        (lo, hi) = (lo - offset, hi - offset);
        for (BoxGrid.Cursor near = entry.Objects.Near(lo, hi); near.MoveNext();)
        {
            ref readonly ObjectBox b = ref entry.ObjectBoxes[near.Current];
            if (!Boxes.Overlaps(b.WallMin, b.WallMax, lo, hi) && Boxes.Overlaps(b.FloorMin, b.FloorMax, lo, hi) && b.ZMax > rise.Top)
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
            && (/* Stryker disable once Logical : true where there is none only plans a move that meets nothing */ !lands.ReachInto(entry).Meets(box.Lo, box.Hi) || CollectAcross(ref lands, entry, in box, ref none)));
    }

    /// <summary>
    /// Whether the body's sweep <paramref name="move"/> (the frame of <paramref name="entry"/>) touches a solid mover, or
    /// starts overlapping one: movers near a move but clear of its sweep leave it on open ground.
    /// </summary>
    public static bool TouchesMover(ref Neighbourhood lands, LandblockEntry entry, in BodyMove move, float moverDrop)
    {
        if (lands.Movers is not MoverFrame movers)
        {
            return /* Stryker disable once Boolean : touching where none is only plans a move that meets nothing */ false;
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
            float t = Math.Clamp(Vector2.Dot(w.A - p, d) / MathF.Max(length2, float.Epsilon), 0f, 1f); // (a move of no length: 0)
            float clear = move.Radius + w.Radius + 0.001f;
            if (w.Radius <= 0f || Vector2.DistanceSquared(p + (d * t), w.A) <= clear * clear)
            {
                return false;
            }
        }

        return /* Stryker disable once Boolean : sweeping a mover that is clear finds nothing */ true;
    }

    [MethodImpl(MethodImplOptions.NoInlining)] // out of the common path: only with movers near
    private static bool MoverTouch(ref Neighbourhood lands, MoverFrame movers, LandblockEntry entry, in BodyMove move, Vector2 lo, Vector2 hi)
    {
        var hit = WallHit.None;
        for (Neighbourhood.MoverCursor near = lands.MoversNear(entry.X, entry.Y, new WallBox(lo, hi, move.ZLow, move.ZHigh)); near.MoveNext();)
        {
            CellWalls walls = movers.Walls[near.Current];
            if (/* Stryker disable once Logical : a mover that does not block is never listed, so a plan for it meets nothing */ lands.Blocks(near.Current) && !Clears(walls, near.Offset, in move))
            {
                MoverSolid.Sweep(walls, near.Offset, lo - near.Offset, hi - near.Offset, in move, ref hit);
                if (/* Stryker disable once Equality : a sweep leaves T at 1 at most; touching where none is only plans a move that meets nothing */ hit.T < 1f || hit.Depth > 0f)
                {
                    return true;
                }
            }
        }

        return /* Stryker disable once Boolean : touching where none is only plans a move that meets nothing */ false;
    }
}
