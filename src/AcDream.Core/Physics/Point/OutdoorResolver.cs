using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Point;

/// <summary>
/// Resolves a move of a mover on the terrain: locates it, wraps the end point into the neighbour
/// landblock across a seam, enters a building's cell whose floor is at the ground there (through a
/// door only, with doors only), else walks the terrain with the step and slope checks.
/// </summary>
internal sealed class OutdoorResolver(WorldFrame frame, PortalTraversal portals)
{
    /// <summary>Resolves one move.</summary>
    /// <remarks>
    /// Never inlined into its caller: inlined into a caller's loop, the whole resolver exhausted the
    /// JIT's inlining budget there, so its small helpers became calls and its answer was copied
    /// through memory (a third slower in the benchmarks). Compiled on its own, it is the same code
    /// for every caller.
    /// </remarks>
    [MethodImpl(MethodImplOptions.NoInlining)]
    public ResolveResult Resolve(ref MoveQuery q)
    {
        // The query's inputs as locals: the hot path then works in registers, not through the reference.
        Vector3 position = q.Position;
        Vector2 delta = q.Delta;
        int lbX, lbY;
        Vector2 local;
        LandblockEntry? here;
        if (q.CellIndex == MoveQuery.Outdoors)
        {
            (here, local) = (q.Here!, q.P0); // located by the body's planner
            (lbX, lbY) = (here.X, here.Y);
        }
        else
        {
            frame.Locate(position, q.CellId, out lbX, out lbY, out local);
            here = q.Lands.Get(lbX, lbY);
        }

        uint hereCellId = WorldFrame.OutdoorCellId(lbX, lbY, local);
        if (here is null)
        {
            return new ResolveResult(position, hereCellId, true) { Outcome = ResolveOutcome.Held }; // the land under the mover is not loaded
        }

        Vector2 candidate = local + delta;
        int toX = lbX, toY = lbY;
        WorldFrame.Wrap(ref candidate.X, ref toX);
        WorldFrame.Wrap(ref candidate.Y, ref toY);
        candidate = frame.Representable(toX, toY, candidate);
        WorldFrame.Wrap(ref candidate.X, ref toX); // rounding can put it on the far seam
        WorldFrame.Wrap(ref candidate.Y, ref toY);
        LandblockEntry? there = toX == lbX && toY == lbY ? here : q.Lands.Get(toX, toY);
        float groundHere = here.Terrain.SampleZUnchecked(local.X, local.Y); // the terrain; objects on the rare paths (GroundHere)

        // Objects are looked at only when the bit of the mover's cell is set (an object is listed on a
        // fine-grid square of the cell or within one square of it), or a move reaching ObjectCellReach
        // or more along an axis has one listed over the squares of its box, or the move comes within the
        // reach of a neighbour's objects (SeamReach) and they reach its box, or it crosses into another landblock: a move away from every object takes the path of a
        // landblock without objects, with the same answer.
        bool objectsNear = (here.ObjectCells & (1UL << (int)((hereCellId & 0xFFFF) - 1))) != 0
            || (!(MathF.Abs(delta.X) < LandblockEntry.ObjectCellReach && MathF.Abs(delta.Y) < LandblockEntry.ObjectCellReach)
                && here.OutdoorObjects.Length > 0 && here.Objects.ListsAny(
                    Vector2.Min(local, local + delta) - new Vector2(PhysicsConstants.NearMargin),
                    Vector2.Max(local, local + delta) + new Vector2(PhysicsConstants.NearMargin)));
        q.Stand = new Standing(lbX, lbY, local, groundHere, hereCellId);
        q.Here = here;
        if (there is null)
        {
            return Refuse(ref q, CellIds.IsInWorld(toX, toY) ? ResolveOutcome.UnloadedAhead : ResolveOutcome.EdgeOfWorld);
        }

        q.Entry = there;
        q.P0 = candidate - delta; // the mover, in the candidate's landblock frame
        q.P1 = candidate;
        float groundZ = there.Terrain.SampleZUnchecked(candidate.X, candidate.Y);
        bool onObject = false;
        Vector2 lo = Vector2.Min(local, local + delta), hi = Vector2.Max(local, local + delta);
        if (objectsNear || there != here || (SeamReach.NearASeam(lo, hi) && q.Lands.ReachInto(here).Meets(lo, hi) && AnyNeighbourNear(ref q.Lands, here, lo, hi)))
        {
            // Among objects: refused at the first object wall the move crosses at the feet plus the step
            // (a shell's is the building's outer wall); else it ends on the highest floor under the end
            // point no more than the step above the feet, the terrain or an object's, and goes on below.
            if (AmongObjects(ref q, position.Z + q.StepUp, ref groundZ, out onObject, out ResolveOutcome why, out Vector3 wallNormal))
            {
                q.ObjectStep = why == ResolveOutcome.StepTooHigh;
                return Refuse(ref q, why, wallNormal);
            }
        }

        return TryEnterCell(there, candidate, groundZ, q.StepUp, out int cellIndex, out float floorZ)
            ? EnterCell(ref q, cellIndex, floorZ)
            : WalkTerrain(ref q, groundZ, onObject);
    }

    /// <summary>Whether a neighbour's outdoor objects meet the box <paramref name="lo"/>–<paramref name="hi"/> (of <paramref name="here"/>'s frame).</summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // out of Resolve: only within a neighbour's reach
    private static bool AnyNeighbourNear(ref Neighbourhood lands, LandblockEntry here, Vector2 lo, Vector2 hi)
    {
        SeamNeighbours across = Neighbourhood.Across(ref lands, here, lo, hi);
        while (across.MoveNext())
        {
            if (across.Current.OutdoorObjects.Length > 0)
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>
    /// The objects' answer for a move among them (of the landblock it ends in and its neighbours, and of the
    /// one it starts in across a seam): whether it crosses an object's wall at the feet plus the step,
    /// <paramref name="h"/> (the outcome: a shell's is the building's outer wall; and the wall's normal);
    /// else <paramref name="groundZ"/> raised to the highest object floor under the end point no higher
    /// than <paramref name="h"/>, and whether it was.
    /// </summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // kept out of Resolve: a move away from objects pays nothing for it
    private static bool AmongObjects(ref MoveQuery q, float h, ref float groundZ, out bool onObject, out ResolveOutcome why, out Vector3 normal)
    {
        var hit = ObjectHit.Over(groundZ);
        ObjectQueries.AmongOutdoors(ref q.Lands, q.Entry, new StepLine(q.P0, q.P1, h), ObjectPass.Both, ref hit);
        if (q.Here != q.Entry)
        {
            ObjectQueries.AmongOutdoors(ref q.Lands, q.Here!, new StepLine(q.Stand.Local, q.Stand.Local + q.Delta, h), ObjectPass.Walls, ref hit);
        }

        if (hit.Wall is null)
        {
            ObjectQueries.RaiseToRest(ref q.Lands, q.Entry, q.P1, q.Z, q.StepUp, ref hit);
        }
        else if (!hit.Rises)
        {
            q.Meet(in hit);
        }

        (groundZ, normal, onObject) = (hit.GroundZ, hit.Normal, hit.Floor is not null);
        why = hit.Rises ? ResolveOutcome.StepTooHigh : hit.Wall is { IsBuilding: true } ? ResolveOutcome.OuterWall : ResolveOutcome.Wall;
        return hit.Wall is not null;
    }

    /// <summary>The move ends over cell <paramref name="cellIndex"/>'s floor at the ground there: entered, unless its edge is a step too high or (doors only) no door leads in.</summary>
    private ResolveResult EnterCell(ref MoveQuery q, int cellIndex, float floorZ)
    {
        if (floorZ - q.Z > q.StepUp && floorZ - MathF.Max(q.Z, GroundHere(ref q)) > q.StepUp)
        {
            return Refuse(ref q, ResolveOutcome.StepTooHigh); // the floor's edge is a step too high
        }

        if (q.Options.DoorsOnly && !q.Entry.Cells[cellIndex].IsShelled && !StartsOverFloor(q.Entry, cellIndex, q.P0, q.Z, q.StepUp))
        {
            uint footprint = q.Entry.Cells[cellIndex].CellId;
            if (!TryEnterByDoor(ref q, out cellIndex, out floorZ))
            {
                q.Meet(SurfaceKind.CellWall, footprint);
                return Refuse(ref q, ResolveOutcome.OuterWall);
            }
        }

        return Answers.Land(frame.ToWorld(q.Entry.X, q.Entry.Y, q.P1, floorZ), q.Z, q.Entry.Cells[cellIndex].CellId, in q.Options);
    }

    /// <summary>
    /// The move ends on the terrain at <paramref name="terrainZ"/> (or on an object's floor there,
    /// <paramref name="onObject"/>: walkable by definition): the storey, step and slope checks, then on it.
    /// </summary>
    private ResolveResult WalkTerrain(ref MoveQuery q, float terrainZ, bool onObject)
    {
        LandblockEntry there = q.Entry;
        if (q.Options.DoorsOnly && StepsIntoStorey(there, q.P0, q.Z, q.P1, terrainZ) is int storey and >= 0)
        {
            q.Meet(SurfaceKind.CellWall, there.Cells[storey].CellId);
            return Refuse(ref q, ResolveOutcome.OuterWall);
        }

        if (terrainZ - q.Z > q.StepUp && terrainZ - MathF.Max(q.Z, GroundHere(ref q)) > q.StepUp)
        {
            q.ObjectStep = onObject;
            return Refuse(ref q, ResolveOutcome.StepTooHigh, there.Terrain.NormalUnchecked(q.P1.X, q.P1.Y));
        }

        if (q.Options.WalkableSlope && !onObject && terrainZ > q.Z && there.Terrain.NormalUnchecked(q.P1.X, q.P1.Y) is var normal && normal.Z < PhysicsConstants.FloorZ)
        {
            return Refuse(ref q, ResolveOutcome.SlopeTooSteep, normal);
        }

        return Answers.Land(frame.ToWorld(there.X, there.Y, q.P1, terrainZ), q.Z, WorldFrame.OutdoorCellId(there.X, there.Y, q.P1), in q.Options);
    }

    /// <summary>A refused move: the mover stays where it stands (<see cref="MoveQuery.Stand"/>), against the terrain's Z under it.</summary>
    private ResolveResult Refuse(ref MoveQuery q, ResolveOutcome why, Vector3 surface = default) =>
        Answers.Refuse(in frame, ref q, in q.Stand, GroundHere(ref q), why, surface);

    /// <summary>
    /// The ground under the mover where it stands: the terrain there (<see cref="Standing.GroundZ"/>), or
    /// an object's floor above it no more than a step above the feet. Asked only on the rare paths (a
    /// rise beyond the step, a refusal), so a move among objects does not pay for it.
    /// </summary>
    private static float GroundHere(ref MoveQuery q) =>
        ObjectQueries.GroundOutdoors(ref q.Lands, q.Here!, q.Stand.Local, q.Z, q.StepUp, q.Stand.GroundZ).GroundZ;

    /// <summary>
    /// Outdoor entry: the floor, among the cells over the candidate's outdoor cell, nearest the
    /// ground the mover would stand on there (<paramref name="z"/>, the terrain's Z) and within the
    /// step height of it (above or below); ties go to the lower cell id. Measuring from the ground
    /// there, not from the feet before the move, makes the answer the same when the mover stands
    /// still at the end point. A floor point on or past one of the cell's doorways to the outdoors is
    /// outdoors: that is where a mover leaving by the door lands.
    /// </summary>
    private static bool TryEnterCell(LandblockEntry entry, Vector2 p, float z, float stepUp, out int cellIndex, out float floorZ)
    {
        cellIndex = -1;
        floorZ = 0f;
        float bestDistance = float.MaxValue;
        foreach (int i in entry.EntryBuckets[CellIds.OutdoorCellNumberUnchecked(p.X, p.Y) - 1])
        {
            if (entry.Cells[i].TrySampleFloor(p.X, p.Y, z, out float candidate) && !IsPastOutdoorDoorway(entry, i, p))
            {
                float distance = MathF.Abs(candidate - z);
                if (distance <= stepUp && distance < bestDistance)
                {
                    cellIndex = i;
                    floorZ = candidate;
                    bestDistance = distance;
                }
            }
        }

        return cellIndex >= 0;
    }

    /// <summary>
    /// Whether <paramref name="p"/> (landblock-local) lies on or beyond the plane of one of cell
    /// <paramref name="cellIndex"/>'s doorways to the outdoors, within <see cref="PhysicsConstants.EdgeTolerance"/>,
    /// measured horizontally.
    /// </summary>
    private static bool IsPastOutdoorDoorway(LandblockEntry entry, int cellIndex, Vector2 p)
    {
        ReadOnlySpan<PortalShape> shapes = entry.Cells[cellIndex].PortalShapes;
        int[] targets = entry.PortalTargets[cellIndex];
        for (int k = 0; k < shapes.Length; k++)
        {
            if (targets[k] == LandblockEntry.OutdoorTarget && shapes[k].Kind == PortalKind.Vertical && shapes[k].HorizontalDistance(p) > -PhysicsConstants.EdgeTolerance)
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>Doors only: whether the mover already stands over the cell's floor (within the step height), so entering it crosses no wall.</summary>
    private static bool StartsOverFloor(LandblockEntry entry, int cellIndex, Vector2 p0, float z, float stepUp) =>
        entry.Cells[cellIndex].TrySampleFloor(p0.X, p0.Y, z, out float floorHere) && MathF.Abs(floorHere - z) <= stepUp;

    /// <summary>
    /// Doors only: the cell (its index; −1 for none) whose storey a move from feet at (<paramref name="p0"/>, <paramref name="z0"/>)
    /// to feet at (<paramref name="p1"/>, <paramref name="z1"/>) (landblock-local) steps into from outside it: onto its floor outline where the floor is a storey at the feet
    /// (<see cref="PhysicsConstants.StoreyBelow"/> below to <see cref="PhysicsConstants.StoreyAbove"/> above),
    /// from where it was not. That is through the building's outer wall.
    /// </summary>
    private static int StepsIntoStorey(LandblockEntry entry, Vector2 p0, float z0, Vector2 p1, float z1)
    {
        foreach (int i in entry.EntryBuckets[CellIds.OutdoorCellNumberUnchecked(p1.X, p1.Y) - 1])
        {
            CellSurface cell = entry.Cells[i];
            if (!cell.IsShelled && cell.TrySampleFloor(p1.X, p1.Y, z1, out float there) && IsStorey(there - z1) && !IsPastOutdoorDoorway(entry, i, p1)
                && !(cell.TrySampleFloor(p0.X, p0.Y, z0, out float here) && IsStorey(here - z0)))
            {
                return i;
            }
        }

        return -1;

        static bool IsStorey(float rise) => rise >= -PhysicsConstants.StoreyBelow && rise <= PhysicsConstants.StoreyAbove;
    }

    /// <summary>
    /// Doors only: the floor the move (p0 → p1 of <paramref name="q"/>, landblock-local) reaches by
    /// passing in through the first portal to the outdoors it crosses (of the cells over the outdoor
    /// cells of p0 and p1), continued as an indoor move from that door's cell, so a door cell thinner
    /// than the move is passed, not mistaken for a wall. False when no door is crossed, the move ends
    /// on no floor beyond it, or that floor is more than the step height up.
    /// </summary>
    private bool TryEnterByDoor(ref MoveQuery q, out int cellIndex, out float floorZ)
    {
        LandblockEntry entry = q.Entry;
        int doorCell = -1;
        float doorT = float.MaxValue;
        FirstDoor(ref q, entry.EntryBuckets[CellIds.OutdoorCellNumberUnchecked(q.P0.X, q.P0.Y) - 1], ref doorCell, ref doorT);
        FirstDoor(ref q, entry.EntryBuckets[CellIds.OutdoorCellNumberUnchecked(q.P1.X, q.P1.Y) - 1], ref doorCell, ref doorT);
        cellIndex = -1;
        floorZ = 0f;
        if (doorCell < 0)
        {
            return false;
        }

        Landing landing = portals.FindLanding(ref q, Hop.Start(doorCell, doorT));
        if (landing.Kind != Arrival.Floor || landing.Z - q.Z > q.StepUp)
        {
            return false;
        }

        cellIndex = landing.CellIndex;
        floorZ = landing.Z;
        return true;
    }

    /// <summary>The cell (among <paramref name="cells"/>) whose portal to the outdoors the move crosses inward first.</summary>
    private static void FirstDoor(ref MoveQuery q, int[] cells, ref int doorCell, ref float doorT)
    {
        foreach (int i in cells)
        {
            ReadOnlySpan<PortalShape> shapes = q.Entry.Cells[i].PortalShapes;
            int[] targets = q.Entry.PortalTargets[i];
            for (int k = 0; k < shapes.Length; k++)
            {
                if (targets[k] != LandblockEntry.OutdoorTarget || shapes[k].Kind != PortalKind.Vertical)
                {
                    continue;
                }

                float t = shapes[k].InwardCrossingFraction(q.P0, q.P1, q.Z, q.StepUp);
                if (t >= 0f && t < doorT)
                {
                    doorCell = i;
                    doorT = t;
                }
            }
        }
    }
}
