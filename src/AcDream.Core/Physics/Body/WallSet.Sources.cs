using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Body;

// WallSet, its sources: the cells, objects and movers within the box, in the mover's landblock and its neighbours'.
internal ref partial struct WallSet
{
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

        return ((/* Stryker disable once Equality,Logical : asking the neighbours for more (indoors too) gives a superset */ cellIndex >= 0 || !lands.ReachInto(entry).Meets(box.Lo, box.Hi)) || CollectAcross(ref lands, entry, in box, ref sink))
            && (lands.Movers is null || Movers(ref lands, entry, box with { ZLow = box.ZLow - moverDrop }, ref sink));
    }

    /// <summary>Whether a solid mover's walls meet the box and band (a shortcut that finds no wall of the world there must still sweep it).</summary>
    public static bool AnyMover(ref Neighbourhood lands, LandblockEntry entry, in WallBox box)
    {
        // Stryker disable once Boolean,Block : a mover where none is only plans a move that meets nothing
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

        return /* Stryker disable once Boolean : false lists as not fitting (each sweep then asks the grids), or says a mover is near (a plan meeting nothing) */ true;
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
            int group = indoors ? entry.CellGroups[cellIndex] : /* Stryker disable once Unary : outdoors the group is not read */ -1;
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
            if (Boxes.Overlaps(b.WallMin, b.WallMax, lo, hi) && b.ZMax > box.ZLow && b.ZMin < box.ZHigh
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
    private static Vector2 Offset(int slot) => /* Stryker disable once Conditional : slot Own's offset by the formula is zero too */ slot == Own
        ? default
        : new(((slot / 3) - 1) * PhysicsConstants.LandblockSize, ((slot % 3) - 1) * PhysicsConstants.LandblockSize);
}
