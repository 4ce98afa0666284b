using System.Diagnostics.CodeAnalysis;
using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Point;

/// <summary>
/// Resolves a move of a mover in an indoor cell: locates it in its cell's landblock, runs the portal
/// search from its cell, and turns the landing into an answer (the step check, walkable slope on
/// terrain beyond a door, the ground rule for refusals).
/// </summary>
internal sealed class IndoorResolver(WorldFrame frame, PortalTraversal portals)
{
    public ResolveResult Resolve(ref MoveQuery q)
    {
        Place place;
        if (q.CellIndex >= 0)
        {
            place = new Place(q.Entry, q.Entry.X, q.Entry.Y, q.P0, q.CellIndex); // located by the body's planner
        }
        else if (!Locator.TryFind(frame, ref q.Lands, q.Position, q.CellId, out place))
        {
            return new ResolveResult(q.Position, q.CellId, true) { Outcome = ResolveOutcome.Held }; // the cell's landblock is not loaded
        }

        (LandblockEntry entry, int cellIndex) = (place.Entry, place.CellIndex);
        q.Entry = entry;
        q.P0 = place.Local;
        q.P1 = frame.Representable(place.X, place.Y, q.P0 + q.Delta);
        CellSurface cell = entry.Cells[cellIndex];
        int start = cell.Objects.Length > 0 ? AboveTheCeiling(entry, cellIndex, q.P0, q.Z) : cellIndex;
        Landing landing = portals.FindLanding(ref q, Hop.Start(start));
        if ((cell.Objects.Length > 0 || (landing.Kind == Arrival.Floor && entry.Cells[landing.CellIndex].Objects.Length > 0))
            && ObjectInTheWay(ref q, cell, landing, out ResolveOutcome why, out Vector3 wall))
        {
            q.ObjectStep = why == ResolveOutcome.StepTooHigh;
            return Refuse(ref q, cell, why, wall);
        }

        switch (landing.Kind)
        {
            case Arrival.Floor or Arrival.Terrain when IsStepTooHigh(cell, q.P0, q.Z, landing.Z, q.StepUp):
                q.ObjectStep = landing.Kind == Arrival.Floor && entry.Cells[landing.CellIndex].Objects.Length > 0; // a floor among objects may be theirs
                return Refuse(ref q, cell, ResolveOutcome.StepTooHigh);
            case Arrival.Floor:
                return Answers.Land(frame.ToWorld(place.X, place.Y, q.P1, landing.Z), q.Z, entry.Cells[landing.CellIndex].CellId, in q.Options);
            case Arrival.Terrain:
                LandblockEntry land = PortalTraversal.Outside(ref q, out _, out _, out _)!;
                Vector2 local = landing.TerrainLocal;
                if (q.Options.WalkableSlope && landing.Z > q.Z
                    && land.Terrain.NormalUnchecked(local.X, local.Y) is var normal && normal.Z < PhysicsConstants.FloorZ)
                {
                    return Refuse(ref q, cell, ResolveOutcome.SlopeTooSteep, normal);
                }

                return Answers.Land(frame.ToWorld(land.X, land.Y, local, landing.Z), q.Z, WorldFrame.OutdoorCellId(land.X, land.Y, local), in q.Options);
            default:
                // A wall, a missing cell, unloaded land, or nothing under the mover at all.
                if (landing.Refusal == ResolveOutcome.Wall && landing.CellIndex >= 0)
                {
                    q.Meet(SurfaceKind.CellWall, entry.Cells[landing.CellIndex].CellId);
                }

                return Refuse(ref q, cell, landing.Refusal, landing.WallNormal);
        }
    }

    /// <summary>
    /// Whether the move crosses a wall of an object standing in its start cell or the cell it lands in, at the
    /// feet plus the step (lower walls are steps), or meets one of their floors rising through that height
    /// (<see cref="ObjectSurface.RisesThrough"/>: <paramref name="why"/> is then a step too high);
    /// <paramref name="normal"/>: the first one's.
    /// </summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // kept out of Resolve: a cell without objects pays nothing for it
    private static bool ObjectInTheWay(ref MoveQuery q, CellSurface cell, Landing landing, out ResolveOutcome why, out Vector3 normal)
    {
        var hit = ObjectHit.Over(0f);
        var line = new StepLine(q.P0, q.P1, q.Z + q.StepUp);
        ObjectQueries.FirstCrossing(cell.Objects, in line, ref hit);
        if (landing.Kind == Arrival.Floor && q.Entry.Cells[landing.CellIndex] is { } there && there != cell)
        {
            ObjectQueries.FirstCrossing(there.Objects, in line, ref hit);
        }

        if (!hit.Rises)
        {
            q.Meet(in hit);
        }

        (why, normal) = (hit.Rises ? ResolveOutcome.StepTooHigh : ResolveOutcome.Wall, hit.Normal);
        return hit.T <= 1f;
    }

    /// <summary>
    /// The cell whose search a move starts in: the cell above when the mover's feet are at or above an
    /// opening in its own cell's ceiling (a horizontal portal leading up, under the mover), which only an
    /// object's floor (a stair rising through the opening) can lift it to; else its own cell. From there
    /// the search still finds the object's floor down through the opening, and the floors beside it above.
    /// </summary>
    private static int AboveTheCeiling(LandblockEntry entry, int cellIndex, Vector2 p, float z)
    {
        ReadOnlySpan<PortalShape> shapes = entry.Cells[cellIndex].PortalShapes;
        int[] targets = entry.PortalTargets[cellIndex];
        for (int k = 0; k < shapes.Length; k++)
        {
            PortalShape shape = shapes[k];
            if (shape.Kind == PortalKind.Horizontal && shape.OutNormal.Z > 0f && targets[k] >= 0
                && shape.ContainsXY(p.X, p.Y) && z >= shape.PlaneZ(p.X, p.Y))
            {
                return targets[k];
            }
        }

        return cellIndex;
    }

    /// <summary>The mover stays where it is, on its own cell's floor if it is at (or below) it.</summary>
    private ResolveResult Refuse(ref MoveQuery q, CellSurface cell, ResolveOutcome why, Vector3 normal = default) =>
        Answers.Refuse(
            in frame, ref q, new Standing(q.Entry.X, q.Entry.Y, q.P0, 0f, q.CellId),
            cell.TrySampleGround(q.P0.X, q.P0.Y, q.Z, q.StepUp, out float floorHere) ? floorHere : null,
            why, normal);

    /// <summary>
    /// A rise is too high when it is more than the step height above the mover's Z, and above the
    /// floor under the mover too where the mover has sunk below that floor (so a mover placed under
    /// its floor can walk out instead of being stuck). The floor is sampled only on that rare path.
    /// </summary>
    private static bool IsStepTooHigh(CellSurface cell, Vector2 p0, float z, float newZ, float stepUp) =>
        newZ - z > stepUp
        && (!cell.TrySampleGround(p0.X, p0.Y, z, stepUp, out float floorHere) || newZ - MathF.Max(z, floorHere) > stepUp);
}
