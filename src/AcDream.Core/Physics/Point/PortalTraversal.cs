using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Point;

/// <summary>
/// Indoor portal traversal: where a move from p0 to p1 that starts in a cell ends, following the
/// doorways it crosses and the floor openings it stands over, through as many cells as it passes
/// (at most <see cref="PhysicsConstants.MaxPortalHops"/> deep and <see cref="PhysicsConstants.MaxCellVisits"/>
/// visits in all). Reads another landblock (through the call's <see cref="Neighbourhood"/>) only to land on
/// the terrain beyond a portal to the outdoors.
/// </summary>
internal sealed class PortalTraversal
{
    /// <summary>
    /// The landblock a move <paramref name="q"/> leaving its cell's landblock through a door to the outdoors ends in
    /// (as read by this call; null when not loaded), with the end point <paramref name="local"/> in its frame and its
    /// indices: where every landing on the terrain is.
    /// </summary>
    public static LandblockEntry? Outside(ref MoveQuery q, out Vector2 local, out int x, out int y)
    {
        local = q.P1;
        (x, y) = (q.Entry.X, q.Entry.Y);
        WorldFrame.Wrap(ref local.X, ref x);
        WorldFrame.Wrap(ref local.Y, ref y);
        return q.Lands.Get(x, y);
    }

    /// <summary>
    /// Where the move <paramref name="q"/> (its entry, p0, p1, feet Z and step) ends when it is in
    /// cell <paramref name="hop"/>.Cell: through the first doorway it crosses (after
    /// <paramref name="hop"/>.TStart along the move), else on this cell's floor, else through a floor
    /// opening under p1, else (first cell only) on a portal neighbour's floor under p1.
    /// </summary>
    public Landing FindLanding(ref MoveQuery q, Hop hop)
    {
        if (--q.CellVisitsLeft < 0)
        {
            return Landing.Blocked(ResolveOutcome.Wall); // the call has visited as many cells as any real move needs
        }

        LandblockEntry entry = q.Entry;
        CellSurface cell = entry.Cells[hop.Cell];
        ReadOnlySpan<PortalShape> shapes = cell.PortalShapes;
        int[] targets = entry.PortalTargets[hop.Cell];

        int doorway = -1;
        float doorwayT = float.MaxValue;
        Vector3 wallNormal = default;
        for (int k = 0; k < shapes.Length; k++)
        {
            if (shapes[k].Kind != PortalKind.Vertical || (targets[k] == hop.From && hop.From >= 0))
            {
                continue;
            }

            float t = shapes[k].CrossingFraction(q.P0, q.P1, q.Z, q.StepUp, out bool crossesPlane);
            if (crossesPlane && t < 0f)
            {
                wallNormal = shapes[k].WallNormal; // crossed the doorway's plane beside its opening: its wall
            }

            if (t >= hop.TStart && t < doorwayT)
            {
                doorway = k;
                doorwayT = t;
            }
        }

        if (doorway >= 0)
        {
            return Pass(ref q, hop, targets[doorway], doorwayT, falling: false); // nothing beyond: a wall (the one it met there, if any)
        }

        if (cell.TrySampleGround(q.P1.X, q.P1.Y, q.Z, q.StepUp, out float floorZ))
        {
            // This cell's floor, unless a floor reached up through an opening in its ceiling is nearer the feet
            // (a mover at the top of a stair steps onto the room's floor beside the opening, not down to the
            // cellar's floor under it).
            return cell.HasOpeningAbove ? NearerAbove(ref q, hop, floorZ) : Landing.OnFloor(hop.Cell, floorZ);
        }

        for (int k = 0; k < shapes.Length; k++)
        {
            PortalShape shape = shapes[k];
            if (shape.Kind != PortalKind.Horizontal || (targets[k] == hop.From && hop.From >= 0) || !shape.ContainsXY(q.P1.X, q.P1.Y))
            {
                continue;
            }

            float planeZ = shape.PlaneZ(q.P1.X, q.P1.Y);
            // With vertical motion a body in the air over an opening is over what lies below it, however high above it is.
            if (planeZ > q.Z + q.StepUp + PhysicsConstants.EdgeTolerance
                || (!hop.Falling && !q.Options.MovesVertically && planeZ < q.Z - q.StepUp - PhysicsConstants.EdgeTolerance))
            {
                continue; // an opening overhead, or one this mover is not standing at
            }

            Landing through = Pass(ref q, hop, targets[k], hop.TStart, falling: true);
            if (through.Kind != Arrival.Nothing)
            {
                return through;
            }
        }

        if (cell.HasOpeningAbove && Upward(ref q, hop, shapes, targets) is { Kind: Arrival.Floor or Arrival.Terrain } upward)
        {
            return upward;
        }

        if (hop.Depth == 0 && wallNormal == default)
        {
            // Portal geometry decided nothing: any portal neighbour with a floor under p1 takes the
            // mover. Not when the move passed a doorway's plane beside its opening: that is the wall.
            int best = -1;
            float bestZ = 0f, bestDistance = float.MaxValue;
            foreach (int target in targets)
            {
                if (target >= 0 && entry.Cells[target].TrySampleGround(q.P1.X, q.P1.Y, q.Z, q.StepUp, out float neighbourZ)
                    && MathF.Abs(neighbourZ - q.Z) < bestDistance)
                {
                    best = target;
                    bestZ = neighbourZ;
                    bestDistance = MathF.Abs(neighbourZ - q.Z);
                }
            }

            if (best >= 0)
            {
                return Landing.OnFloor(best, bestZ);
            }
        }

        return Landing.Nothing(hop.Cell, wallNormal);
    }

    /// <summary>The cell's own floor at <paramref name="floorZ"/>, or the floor reached up through an opening in its ceiling when that is nearer the feet.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // out of the search's common path: only cells with an opening above
    private Landing NearerAbove(ref MoveQuery q, Hop hop, float floorZ)
    {
        LandblockEntry entry = q.Entry;
        Landing up = Upward(ref q, hop, entry.Cells[hop.Cell].PortalShapes, entry.PortalTargets[hop.Cell]);
        return up.Kind is Arrival.Floor or Arrival.Terrain && MathF.Abs(up.Z - q.Z) < MathF.Abs(floorZ - q.Z) ? up : Landing.OnFloor(hop.Cell, floorZ);
    }

    /// <summary>
    /// Through an opening in the ceiling of cell <paramref name="hop"/>.Cell that the move passes under, no more than
    /// the step above the feet: the mover climbs up through it (a stair rising into the opening, left at its top
    /// edge onto the floor above, whatever the length of the move). The search goes on above, where the floor
    /// beside the opening is found, or a further opening (a shaft's) is climbed the same way. Nothing when no such
    /// opening leads to a floor.
    /// </summary>
    private Landing Upward(ref MoveQuery q, Hop hop, ReadOnlySpan<PortalShape> shapes, int[] targets)
    {
        for (int k = 0; k < shapes.Length; k++)
        {
            PortalShape shape = shapes[k];
            float reach = q.Z + q.StepUp + PhysicsConstants.EdgeTolerance;
            if (shape.Kind != PortalKind.Horizontal || shape.OutNormal.Z <= 0f || (targets[k] == hop.From && hop.From >= 0) || shape.ZMin > reach
                || shape.BoundsMin.X - PhysicsConstants.EdgeTolerance > MathF.Max(q.P0.X, q.P1.X) || shape.BoundsMax.X + PhysicsConstants.EdgeTolerance < MathF.Min(q.P0.X, q.P1.X)
                || shape.BoundsMin.Y - PhysicsConstants.EdgeTolerance > MathF.Max(q.P0.Y, q.P1.Y) || shape.BoundsMax.Y + PhysicsConstants.EdgeTolerance < MathF.Min(q.P0.Y, q.P1.Y)
                || MathF.Min(shape.PlaneZ(q.P0.X, q.P0.Y), shape.PlaneZ(q.P1.X, q.P1.Y)) > reach
                || !shape.SegmentTouchesXY(q.P0, q.P1))
            {
                continue;
            }

            Landing through = Pass(ref q, hop, targets[k], hop.TStart, falling: false);
            if (through.Kind is Arrival.Floor or Arrival.Terrain)
            {
                return through;
            }
        }

        return default;
    }

    /// <summary>The landing beyond a portal of cell <paramref name="hop"/>.Cell leading to <paramref name="target"/>, crossed at fraction <paramref name="t"/>.</summary>
    private Landing Pass(ref MoveQuery q, Hop hop, int target, float t, bool falling)
    {
        if (target == LandblockEntry.MissingCell || hop.Depth >= PhysicsConstants.MaxPortalHops)
        {
            return Landing.Blocked(ResolveOutcome.Wall, hop.Cell);
        }

        if (target == LandblockEntry.OutdoorTarget)
        {
            LandblockEntry? land = Outside(ref q, out Vector2 local, out int x, out int y);
            return land is null
                ? Landing.Blocked(CellIds.IsInWorld(x, y) ? ResolveOutcome.UnloadedAhead : ResolveOutcome.EdgeOfWorld)
                : Landing.OnTerrain(local, land.Terrain.SampleZUnchecked(local.X, local.Y));
        }

        return FindLanding(ref q, new Hop(target, hop.Cell, hop.Depth + 1, t, falling));
    }
}

/// <summary>
/// One cell of a portal search: the cell, the one it was entered from (−1 for the first), how deep,
/// how far along the move its doorways count from, and whether the mover dropped in through an opening.
/// </summary>
internal readonly record struct Hop(int Cell, int From, int Depth, float TStart, bool Falling)
{
    /// <summary>The first cell of a move: the mover's own.</summary>
    public static Hop Start(int cell, float tStart = 0f) => new(cell, Landing.NoCell, 0, tStart, false);
}

/// <summary>What a portal search arrived on.</summary>
internal enum Arrival
{
    /// <summary>No surface found.</summary>
    Nothing,

    /// <summary>A wall, a missing cell or unloaded land is in the way.</summary>
    Blocked,

    /// <summary>On a cell's floor.</summary>
    Floor,

    /// <summary>On the terrain, through a portal to the outdoors.</summary>
    Terrain,
}

/// <summary>
/// The end of a portal search: a floor, the terrain beyond a door (its landblock is
/// <see cref="PortalTraversal.Outside"/>), or why there is none, with the cell whose wall it met when it
/// knows it. No object reference: a landing is a plain value, so the many a search returns need no zeroing.
/// </summary>
internal readonly record struct Landing(Arrival Kind, int CellIndex, float Z, Vector2 TerrainLocal, ResolveOutcome Refusal, Vector3 WallNormal)
{
    /// <summary>The <see cref="CellIndex"/> of a landing that is not on a cell's floor (and a first hop's <see cref="Hop.From"/>).</summary>
    public const int NoCell = -1;

    /// <summary>No floor ahead in cell <paramref name="cell"/> (its index): its wall.</summary>
    public static Landing Nothing(int cell, Vector3 wallNormal) => new(Arrival.Nothing, cell, 0f, default, ResolveOutcome.Wall, wallNormal);

    /// <summary>Blocked; <paramref name="cell"/> is the index of the cell whose wall (a portal to a cell the engine does not have) it is, when known.</summary>
    public static Landing Blocked(ResolveOutcome why, int cell = NoCell) => new(Arrival.Blocked, cell, 0f, default, why, default);

    public static Landing OnFloor(int cellIndex, float z) => new(Arrival.Floor, cellIndex, z, default, ResolveOutcome.Moved, default);

    /// <summary>On the terrain at <paramref name="local"/> of the landblock outside (<see cref="PortalTraversal.Outside"/>).</summary>
    public static Landing OnTerrain(Vector2 local, float z) => new(Arrival.Terrain, NoCell, z, local, ResolveOutcome.Moved, default);
}
