using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>
/// The walls around one body move: every wall it can meet is found where a sweep asks for it, in the
/// landblock's grids (<see cref="LandblockEntry.CellWalls"/>, <see cref="LandblockEntry.Objects"/>) over the
/// sweep's own box, nothing gathered beforehand and nothing left out however many walls stand near. Indoors:
/// the walls of the landblock's cells and of the objects standing in them. Outdoors: the walls of its
/// buildings' cells and its outdoor objects, and those of a neighbouring landblock whose own reach the box
/// meets across a seam (read through the call's <see cref="Neighbourhood"/>, so each once). All in the mover's
/// landblock frame (landblock-local metres); allocation-free.
/// </summary>
internal ref struct WallSet
{
    private readonly ref Neighbourhood _lands;
    private readonly LandblockEntry _entry;
    private readonly bool _indoors;

    /// <summary>The walls around a mover in landblock <paramref name="entry"/> (indoors: in one of its cells).</summary>
    public WallSet(ref Neighbourhood lands, LandblockEntry entry, bool indoors)
    {
        _lands = ref lands;
        _entry = entry;
        _indoors = indoors;
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
        var sweep = new Sweeper(move, hit);
        Visit(lo, hi, ref sweep);
        hit = sweep.Hit;
    }

    /// <summary>Whether any wall's bounds (seen from above) meet the box <paramref name="lo"/>–<paramref name="hi"/>: false is certain.</summary>
    public readonly bool Any(Vector2 lo, Vector2 hi)
    {
        var any = new AnyWall();
        Visit(lo, hi, ref any);
        return any.Found;
    }

    /// <summary>Hands every cell and object whose walls' bounds may meet the box to <paramref name="visitor"/>, until it stops.</summary>
    private readonly void Visit<T>(Vector2 lo, Vector2 hi, ref T visitor)
        where T : struct, IWallVisitor
    {
        if (_indoors)
        {
            Visit(_entry, default, lo, hi, ref visitor);
            return;
        }

        if (!Visit(_entry, default, lo, hi, ref visitor))
        {
            return;
        }

        SeamNeighbours across = Neighbourhood.Across(ref _lands, _entry, lo, hi);
        while (across.MoveNext() && Visit(across.Current, across.Offset, lo, hi, ref visitor))
        {
        }
    }

    /// <summary>One landblock's walls (its frame <paramref name="offset"/> from the mover's) for the box; false when the visitor stopped.</summary>
    private readonly bool Visit<T>(LandblockEntry entry, Vector2 offset, Vector2 lo, Vector2 hi, ref T visitor)
        where T : struct, IWallVisitor
    {
        lo -= offset;
        hi -= offset;
        var cells = new CellVisit<T>(entry, offset, lo, hi, ref visitor);
        if ((_indoors ? entry.CellWalls : entry.OutdoorCellWalls) is BoxGrid cellGrid && !cellGrid.Query(lo, hi, ref cells))
        {
            return false;
        }

        if (_indoors || entry.OutdoorObjects.Length == 0)
        {
            return true;
        }

        var objects = new ObjectVisit<T>(entry, offset, lo, hi, ref visitor);
        return entry.Objects.Query(lo, hi, ref objects);
    }

    /// <summary>A cell of the grid: its walls and its objects' walls.</summary>
    private ref struct CellVisit<T>(LandblockEntry entry, Vector2 offset, Vector2 lo, Vector2 hi, ref T visitor) : IBoxVisitor
        where T : struct, IWallVisitor
    {
        private ref T _visitor = ref visitor;

        public bool Visit(int item)
        {
            CellSurface cell = entry.Cells[item];
            if (!_visitor.Walls(cell.Walls, offset, lo, hi))
            {
                return false;
            }

            foreach (ObjectSurface o in cell.Objects)
            {
                if (!_visitor.Walls(o.Walls, offset, lo, hi))
                {
                    return false;
                }
            }

            return true;
        }
    }

    /// <summary>An outdoor object of the fine grid: its box's walls' bounds first, then its walls.</summary>
    private ref struct ObjectVisit<T>(LandblockEntry entry, Vector2 offset, Vector2 lo, Vector2 hi, ref T visitor) : IBoxVisitor
        where T : struct, IWallVisitor
    {
        private ref T _visitor = ref visitor;

        public bool Visit(int item)
        {
            ref readonly ObjectBox b = ref entry.ObjectBoxes[item];
            return b.WallMin.X > hi.X || b.WallMax.X < lo.X || b.WallMin.Y > hi.Y || b.WallMax.Y < lo.Y
                || _visitor.Walls(entry.OutdoorObjects[item].Walls, offset, lo, hi);
        }
    }

    /// <summary>Sweeps a body move against the walls handed to it.</summary>
    private struct Sweeper(BodyMove move, WallHit hit) : IWallVisitor
    {
        private readonly BodyMove _move = move;

        public WallHit Hit = hit;

        public bool Walls(CellWalls walls, Vector2 offset, Vector2 lo, Vector2 hi)
        {
            BodySweep.SweepWalls(walls, offset, lo, hi, in _move, ref Hit);
            return true;
        }
    }

    /// <summary>Stops at the first walls whose bounds meet the box.</summary>
    private struct AnyWall : IWallVisitor
    {
        public bool Found;

        public bool Walls(CellWalls walls, Vector2 offset, Vector2 lo, Vector2 hi)
        {
            Found = walls.Polygons.Length > 0 && walls.Min.X <= hi.X && walls.Max.X >= lo.X && walls.Min.Y <= hi.Y && walls.Max.Y >= lo.Y;
            return !Found;
        }
    }
}

/// <summary>What <see cref="WallSet"/> hands one cell's or object's walls to, with the box in their landblock's frame.</summary>
internal interface IWallVisitor
{
    /// <summary>Handles <paramref name="walls"/> (their landblock frame <paramref name="offset"/> from the mover's; the box <paramref name="lo"/>–<paramref name="hi"/> in theirs); false stops the visit.</summary>
    bool Walls(CellWalls walls, Vector2 offset, Vector2 lo, Vector2 hi);
}
