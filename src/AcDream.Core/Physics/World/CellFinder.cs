using System.Numerics;
using AcDream.Core.Physics.Surfaces;

namespace AcDream.Core.Physics.World;

/// <summary>
/// Which cell holds a point (<see cref="PhysicsEngine.FindCell"/>): among the indoor cells reached through portals from
/// a hint, the one whose floor is nearest under the point; else the outdoor cell under it.
/// </summary>
internal static class CellFinder
{
    /// <summary>The cell that holds <paramref name="position"/>, searched from <paramref name="hintCellId"/> (checked by the caller).</summary>
    public static uint Find(in WorldFrame frame, ref Neighbourhood lands, Vector3 position, uint hintCellId)
    {
        int x, y;
        Vector2 local;
        LandblockEntry? entry;
        Span<int> queue = stackalloc int[PhysicsConstants.MaxCellVisits];
        int count = 0;
        if (CellIds.IsIndoor(hintCellId))
        {
            (x, y) = (CellIds.LandblockX(hintCellId), CellIds.LandblockY(hintCellId));
            entry = lands.Get(x, y);
            if (entry is not null)
            {
                if (!entry.TryGetCellIndex(hintCellId, out int hint))
                {
                    Locator.ThrowNotRegistered(hintCellId, nameof(hintCellId));
                }

                local = frame.Representable(x, y, new Vector2(position.X, position.Y) - frame.Origin(x, y));
                queue[count++] = hint;
                if (Search(entry, local, position.Z, queue, count) is int found)
                {
                    return entry.Cells[found].CellId;
                }
            }
        }

        frame.Locate(position, CellIds.IsIndoor(hintCellId) ? 0u : hintCellId, out x, out y, out local);
        entry = lands.Get(x, y);
        if (entry is not null)
        {
            // From outdoors the portals lead in through the cells with a portal to the outdoors: the doors.
            count = 0;
            for (int i = 0; i < entry.Cells.Length && count < queue.Length; i++)
            {
                count += entry.PortalTargets[i].AsSpan().Contains(LandblockEntry.OutdoorTarget) ? Push(queue, count, i) : 0;
            }

            if (count > 0 && Search(entry, local, position.Z, queue, count) is int found)
            {
                return entry.Cells[found].CellId;
            }
        }

        return WorldFrame.OutdoorCellId(x, y, local);
    }

    private static int Push(Span<int> queue, int count, int cell)
    {
        queue[count] = cell;
        return 1;
    }

    /// <summary>
    /// Breadth first through the portals from the first <paramref name="seeds"/> cells of <paramref name="queue"/>, at most
    /// <see cref="PhysicsConstants.MaxCellVisits"/> cells: the cell that holds the point with the highest floor, or null.
    /// </summary>
    private static int? Search(LandblockEntry entry, Vector2 local, float z, Span<int> queue, int seeds)
    {
        int? best = null;
        float bestFloor = float.NegativeInfinity;
        for (int head = 0, count = seeds; head < count; head++)
        {
            int cell = queue[head];
            if (Holds(entry, cell, local, z, out float floor) && floor > bestFloor)
            {
                (best, bestFloor) = (cell, floor);
            }

            foreach (int next in entry.PortalTargets[cell])
            {
                if (next >= 0 && count < queue.Length && !queue[..count].Contains(next))
                {
                    queue[count++] = next;
                }
            }
        }

        return best;
    }

    /// <summary>
    /// Whether cell <paramref name="index"/> holds the point: a floor of it lies under the point's XY at or below it (within
    /// <see cref="PhysicsConstants.GroundTolerance"/>), and the point is not above the cell's walls.
    /// </summary>
    private static bool Holds(LandblockEntry entry, int index, Vector2 local, float z, out float floor)
    {
        const float tolerance = PhysicsConstants.GroundTolerance;
        CellSurface cell = entry.Cells[index];
        WallBounds bounds = entry.CellWallBounds[index];
        return cell.TrySampleFloor(local.X, local.Y, z, out floor) && floor <= z + tolerance
            && !(bounds.ZMax >= bounds.ZMin && z > bounds.ZMax + tolerance);
    }
}
