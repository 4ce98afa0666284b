using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>
/// Top-level resolver that owns the per-landblock terrain surfaces and per-cell indoor surfaces.
/// </summary>
/// <remarks>
/// <para>
/// World frame: metres, +X east, +Y north, +Z up. <see cref="PhysicsEngine()"/> uses global
/// coordinates (landblock X·192 + local x); <see cref="PhysicsEngine(uint)"/> puts the origin at the
/// south-west corner of a centre landblock, so positions near it keep full float precision.
/// Internally every query runs in the landblock-local frame (0..192 m), so the answers do not
/// depend on where in the world the landblock is; only the returned world position is rounded to
/// the float spacing at its magnitude (about 4 mm at the far corner of the global frame).
/// </para>
/// <para>
/// Not thread-safe: register, remove and resolve from one thread (the frame loop). Resolve is
/// stateless per call and allocates nothing.
/// </para>
/// </remarks>
public sealed class PhysicsEngine
{
    private const int WorldSide = 256;

    /// <summary>
    /// How far (metres) an outdoor mover may stand outside the landblock its cell id names and still
    /// be resolved from that landblock: covers the rounding of world positions at seams far from the
    /// origin, where a position can round onto the neighbour's side of the seam.
    /// </summary>
    private const float SeamSlack = 1f;

    /// <summary>Most sub-steps one swept move takes (see <see cref="MovementOptions.SweepStepLength"/>).</summary>
    private const int MaxSweepSteps = 1 << 16;

    /// <summary>The options of the four-argument Resolve: no effects.</summary>
    private static readonly MovementOptions NoEffects = default;

    private readonly LandblockEntry?[] _landblocks = new LandblockEntry?[WorldSide * WorldSide];
    private readonly int _originX;
    private readonly int _originY;

    /// <summary>An engine whose world frame is global: world = landblock X·192 + landblock-local metres.</summary>
    public PhysicsEngine()
    {
    }

    /// <summary>
    /// An engine whose world frame is centred on a landblock: world (0, 0) is the south-west corner
    /// of <paramref name="centerLandblockId"/>, so world = (X − centreX)·192 + landblock-local metres.
    /// </summary>
    /// <param name="centerLandblockId">The centre landblock, <c>0xXXYYFFFF</c> or <c>0xXXYY0000</c>.</param>
    /// <exception cref="ArgumentException">The id is not a landblock id of the world.</exception>
    public PhysicsEngine(uint centerLandblockId)
    {
        CellIds.ValidateLandblockId(centerLandblockId, nameof(centerLandblockId));
        _originX = CellIds.LandblockX(centerLandblockId);
        _originY = CellIds.LandblockY(centerLandblockId);
    }

    /// <summary>Number of registered landblocks.</summary>
    public int LandblockCount { get; private set; }

    /// <summary>Whether a landblock (any low 16 bits) is registered.</summary>
    public bool ContainsLandblock(uint landblockId) =>
        _landblocks[CellIds.LandblockIndex(CellIds.LandblockX(landblockId), CellIds.LandblockY(landblockId))] is not null;

    /// <summary>
    /// World position (metres, Z = 0) of the south-west corner of a landblock: add landblock-local
    /// coordinates to it to get world coordinates.
    /// </summary>
    public Vector3 GetLandblockOrigin(uint landblockId) =>
        new(Offset(CellIds.LandblockX(landblockId), _originX), Offset(CellIds.LandblockY(landblockId), _originY), 0f);

    /// <summary>
    /// Register terrain + EnvCell surfaces for a loaded landblock.
    /// Called from the render thread in ApplyLoadedTerrain.
    /// </summary>
    /// <remarks>
    /// Registering a landblock that is already registered replaces it. Every argument is checked
    /// before anything changes: on an exception the engine is as it was.
    /// </remarks>
    /// <param name="landblockId">The landblock, <c>0xXXYYFFFF</c> or <c>0xXXYY0000</c>.</param>
    /// <param name="terrain">Its terrain; if built with a landblock id, that id must be this one.</param>
    /// <param name="cells">Its indoor cells (may be empty); every id must carry this landblock's prefix, once.</param>
    /// <exception cref="ArgumentNullException">An argument or a cell is null.</exception>
    /// <exception cref="ArgumentException">The id is not a landblock id, the terrain belongs to another landblock, or a cell is of another landblock or listed twice.</exception>
    public void AddLandblock(
        uint landblockId,
        TerrainSurface terrain,
        IReadOnlyList<CellSurface> cells)
    {
        CellIds.ValidateLandblockId(landblockId, nameof(landblockId));
        ArgumentNullException.ThrowIfNull(terrain);
        ArgumentNullException.ThrowIfNull(cells);
        uint prefix = CellIds.Prefix(landblockId);
        if (terrain.LandblockId is uint terrainId && CellIds.Prefix(terrainId) != prefix)
        {
            throw new ArgumentException(
                $"landblock 0x{prefix | 0xFFFF:X8}: the terrain was built for landblock 0x{terrainId:X8}.", nameof(terrain));
        }

        var sorted = new CellSurface[cells.Count];
        for (int i = 0; i < sorted.Length; i++)
        {
            CellSurface cell = cells[i] ?? throw new ArgumentNullException(nameof(cells), $"landblock 0x{prefix | 0xFFFF:X8}: cells[{i}] is null.");
            if (CellIds.Prefix(cell.CellId) != prefix)
            {
                throw new ArgumentException(
                    $"landblock 0x{prefix | 0xFFFF:X8}: cell 0x{cell.CellId:X8} belongs to another landblock.", nameof(cells));
            }

            sorted[i] = cell;
        }

        Array.Sort(sorted, static (a, b) => a.CellId.CompareTo(b.CellId));
        for (int i = 1; i < sorted.Length; i++)
        {
            if (sorted[i].CellId == sorted[i - 1].CellId)
            {
                throw new ArgumentException(
                    $"landblock 0x{prefix | 0xFFFF:X8}: cell 0x{sorted[i].CellId:X8} is listed twice.", nameof(cells));
            }
        }

        int x = CellIds.LandblockX(landblockId), y = CellIds.LandblockY(landblockId);
        ref LandblockEntry? slot = ref _landblocks[CellIds.LandblockIndex(x, y)];
        if (slot is null)
        {
            LandblockCount++;
        }

        slot = new LandblockEntry(x, y, terrain, sorted);
    }

    /// <summary>Remove all surfaces for an unloaded landblock.</summary>
    /// <remarks>Any low 16 bits are accepted. Removing a landblock that is not registered does nothing, so an unload path may call it unconditionally.</remarks>
    public void RemoveLandblock(uint landblockId)
    {
        ref LandblockEntry? slot = ref _landblocks[CellIds.LandblockIndex(CellIds.LandblockX(landblockId), CellIds.LandblockY(landblockId))];
        if (slot is not null)
        {
            slot = null;
            LandblockCount--;
        }
    }

    /// <summary>
    /// Resolve a movement step. Given the entity's current world
    /// position + cell id + a movement delta + a step-up height limit,
    /// return the valid resolved position and the cell id the entity
    /// ends up in.
    /// </summary>
    /// <remarks>
    /// <para>
    /// Positions and the delta are world metres. Only the horizontal part of <paramref name="delta"/>
    /// moves the mover; its Z is ignored (the caller's gravity moves <paramref name="currentPos"/>.Z).
    /// A rise of exactly <paramref name="stepUpHeight"/> is accepted; more is rejected and the
    /// mover keeps the XY of <paramref name="currentPos"/>. See <c>docs/physics.md</c> for the algorithm.
    /// </para>
    /// <para>
    /// The answer is computed at the XY it returns (the end point rounded to the world frame first),
    /// so resolving it again with a zero delta returns it bit for bit. A refused mover keeps its Z
    /// when within <see cref="PhysicsConstants.GroundTolerance"/> of the ground under it; below the
    /// ground it is lifted onto it; above it, it keeps its Z with <c>IsOnGround</c> false.
    /// </para>
    /// <para>
    /// A mover whose landblock is not registered (streaming has not caught up) is held where it is,
    /// on the ground, so it does not fall through land that is not loaded. A move into such a
    /// landblock, or off the world, is rejected. When nothing is under an indoor mover, the result
    /// keeps its position and reports <c>IsOnGround = false</c>. One call visits at most
    /// <see cref="PhysicsConstants.MaxCellVisits"/> cells, whatever the portal graph.
    /// </para>
    /// </remarks>
    /// <param name="currentPos">Where the mover's feet are, world metres.</param>
    /// <param name="currentCellId">The cell the mover is in (<c>0xXXYYCCCC</c>); for an outdoor mover any outdoor number, 0 included, is accepted and recomputed from the position.</param>
    /// <param name="delta">The intended move, world metres.</param>
    /// <param name="stepUpHeight">Highest rise one move may climb, metres, ≥ 0.</param>
    /// <exception cref="ArgumentException">An argument is NaN or infinite, the step height is negative, the cell number is not a cell (0x0041..0x00FF, 0xFFFE, 0xFFFF), the id's landblock X or Y is off the world (0xFF), or an indoor cell is not in its registered landblock.</exception>
    public ResolveResult Resolve(
        Vector3 currentPos,
        uint currentCellId,
        Vector3 delta,
        float stepUpHeight)
    {
        Validate(currentPos, currentCellId, delta, stepUpHeight);
        return ResolveStep(currentPos, currentCellId, new Vector2(delta.X, delta.Y), stepUpHeight, in NoEffects, out _);
    }

    /// <summary>
    /// <see cref="Resolve(Vector3, uint, Vector3, float)"/> with opt-in effects beyond the spec. With
    /// <c>default(MovementOptions)</c> the answer is bit for bit that of the four-argument call.
    /// </summary>
    /// <param name="currentPos">Where the mover's feet are, world metres.</param>
    /// <param name="currentCellId">The cell the mover is in (<c>0xXXYYCCCC</c>).</param>
    /// <param name="delta">The intended move, world metres; its Z is ignored.</param>
    /// <param name="stepUpHeight">Highest rise one move (one sub-step when sweeping) may climb, metres, ≥ 0.</param>
    /// <param name="options">The effects to simulate; see <see cref="MovementOptions"/>.</param>
    /// <returns>
    /// As the four-argument call; with <see cref="MovementOptions.SweepStepLength"/> a move stopped part
    /// way returns the last sub-step that was accepted, and with <see cref="MovementOptions.StepDownHeight"/>
    /// an airborne mover is reported with <c>IsOnGround</c> false over the cell below it.
    /// </returns>
    /// <exception cref="ArgumentException">As the four-argument call.</exception>
    public ResolveResult Resolve(
        Vector3 currentPos,
        uint currentCellId,
        Vector3 delta,
        float stepUpHeight,
        in MovementOptions options)
    {
        Validate(currentPos, currentCellId, delta, stepUpHeight);
        var move = new Vector2(delta.X, delta.Y);
        if (options.SweepStepLength is float sweep && move.LengthSquared() > sweep * sweep)
        {
            return Sweep(currentPos, currentCellId, move, stepUpHeight, in options, sweep);
        }

        return ResolveStep(currentPos, currentCellId, move, stepUpHeight, in options, out _);
    }

    /// <summary>Equal sub-steps no longer than <paramref name="sweep"/>, stopping at the first rejected one.</summary>
    private ResolveResult Sweep(Vector3 pos, uint cellId, Vector2 move, float stepUp, in MovementOptions options, float sweep)
    {
        int steps = (int)Math.Min(Math.Ceiling(move.Length() / (double)sweep), MaxSweepSteps);
        Vector2 step = move / steps;
        ResolveResult result = ResolveStep(pos, cellId, step, stepUp, in options, out bool rejected);
        for (int i = 1; i < steps && !rejected; i++)
        {
            ResolveResult next = ResolveStep(result.Position, result.CellId, step, stepUp, in options, out rejected);
            if (!rejected)
            {
                result = next;
            }
        }

        return result;
    }

    /// <summary>One move, end-point checked. <paramref name="rejected"/>: the mover was kept where it was.</summary>
    private ResolveResult ResolveStep(Vector3 pos, uint cellId, Vector2 delta, float stepUp, in MovementOptions options, out bool rejected) =>
        CellIds.IsIndoor(cellId)
            ? ResolveIndoor(pos, cellId, delta, stepUp, in options, out rejected)
            : ResolveOutdoor(pos, cellId, delta, stepUp, in options, out rejected);

    private ResolveResult ResolveOutdoor(Vector3 pos, uint cellId, Vector2 delta, float stepUp, in MovementOptions options, out bool rejected)
    {
        rejected = true;
        Locate(pos, cellId, out int lbX, out int lbY, out Vector2 local);
        LandblockEntry? here = GetEntry(lbX, lbY);
        uint hereCellId = OutdoorCellId(lbX, lbY, local);
        if (here is null)
        {
            return new ResolveResult(pos, hereCellId, true); // held: the land under the mover is not loaded
        }

        Vector2 candidate = local + delta;
        int toX = lbX, toY = lbY;
        Wrap(ref candidate.X, ref toX);
        Wrap(ref candidate.Y, ref toY);
        candidate = Representable(toX, toY, candidate);
        Wrap(ref candidate.X, ref toX); // rounding can put it on the far seam
        Wrap(ref candidate.Y, ref toY);
        LandblockEntry? there = GetEntry(toX, toY);
        if (there is null)
        {
            return Refuse(lbX, lbY, local, pos.Z, here.Terrain.SampleZUnchecked(local.X, local.Y), hereCellId, in options); // unloaded land or off the world
        }

        Vector2 start = candidate - delta; // the mover, in the candidate's landblock frame
        float hereZ = here.Terrain.SampleZUnchecked(local.X, local.Y);
        float terrainZ = there.Terrain.SampleZUnchecked(candidate.X, candidate.Y);
        if (TryEnterCell(there, candidate, terrainZ, stepUp, out int cellIndex, out float floorZ))
        {
            if (floorZ - pos.Z > stepUp && floorZ - MathF.Max(pos.Z, hereZ) > stepUp)
            {
                return Refuse(lbX, lbY, local, pos.Z, hereZ, hereCellId, in options); // the floor's edge is a step too high
            }

            if (options.DoorsOnly
                && !StartsOverFloor(there, cellIndex, start, pos.Z, stepUp)
                && !TryEnterByDoor(there, start, candidate, pos.Z, stepUp, out cellIndex, out floorZ))
            {
                return Refuse(lbX, lbY, local, pos.Z, here.Terrain.SampleZUnchecked(local.X, local.Y), hereCellId, in options); // the building's outer wall
            }

            rejected = false;
            return Land(ToWorld(toX, toY, candidate, floorZ), pos.Z, there.Cells[cellIndex].CellId, in options);
        }

        if (options.DoorsOnly && StepsIntoStorey(there, start, pos.Z, candidate, terrainZ))
        {
            return Refuse(lbX, lbY, local, pos.Z, hereZ, hereCellId, in options); // the building's outer wall
        }

        if (terrainZ - pos.Z > stepUp && terrainZ - MathF.Max(pos.Z, hereZ) > stepUp)
        {
            return Refuse(lbX, lbY, local, pos.Z, hereZ, hereCellId, in options); // step too high
        }

        if (options.WalkableSlope && terrainZ > pos.Z && there.Terrain.NormalZUnchecked(candidate.X, candidate.Y) < PhysicsConstants.FloorZ)
        {
            return Refuse(lbX, lbY, local, pos.Z, hereZ, hereCellId, in options); // climbing a slope too steep to walk
        }

        rejected = false;
        return Land(ToWorld(toX, toY, candidate, terrainZ), pos.Z, OutdoorCellId(toX, toY, candidate), in options);
    }

    /// <summary>
    /// The result of arriving over ground at <paramref name="ground"/>: on it, or, with step down on
    /// and the ground farther below the feet than the step-down height, airborne at the feet's Z.
    /// </summary>
    private static ResolveResult Land(Vector3 ground, float z, uint cellId, in MovementOptions options) =>
        options.StepDownHeight is float down && z - ground.Z > MathF.Max(down, PhysicsConstants.GroundTolerance)
            ? new ResolveResult(ground with { Z = z }, cellId, false)
            : new ResolveResult(ground, cellId, true);

    /// <summary>
    /// A refused move: the mover stays at <paramref name="local"/> (landblock-local, in landblock
    /// (lbX, lbY)). Against <paramref name="ground"/> (the terrain, or its cell's floor nearest its
    /// feet, under it; null when there is none): feet within <see cref="PhysicsConstants.GroundTolerance"/>
    /// of it keep their Z and stand on it (the spec's "keep currentPos"); feet deeper below it (sunk), or
    /// above it by no more than the step-down height, are put on it; feet higher keep their Z and are
    /// airborne, so the caller's gravity acts.
    /// </summary>
    private ResolveResult Refuse(int lbX, int lbY, Vector2 local, float z, float? ground, uint cellId, in MovementOptions options)
    {
        if (ground is float g)
        {
            float above = z - g;
            if (MathF.Abs(above) <= PhysicsConstants.GroundTolerance)
            {
                return new ResolveResult(ToWorld(lbX, lbY, local, z), cellId, true);
            }

            if (above < 0f || (options.StepDownHeight is float down && above <= down))
            {
                return new ResolveResult(ToWorld(lbX, lbY, local, g), cellId, true);
            }
        }

        return new ResolveResult(ToWorld(lbX, lbY, local, z), cellId, false);
    }

    /// <summary>
    /// Doors only: whether a move from feet at (<paramref name="p0"/>, <paramref name="z0"/>) to feet at
    /// (<paramref name="p1"/>, <paramref name="z1"/>) (landblock-local) steps into the storey of a cell
    /// from outside it: onto its floor outline where the floor is a storey at the feet
    /// (<see cref="PhysicsConstants.StoreyBelow"/> below to <see cref="PhysicsConstants.StoreyAbove"/> above),
    /// from where it was not. That is through the building's outer wall.
    /// </summary>
    private static bool StepsIntoStorey(LandblockEntry entry, Vector2 p0, float z0, Vector2 p1, float z1)
    {
        foreach (int i in entry.EntryBuckets[OutdoorCellNumber(p1) - 1])
        {
            CellSurface cell = entry.Cells[i];
            if (cell.TrySampleFloor(p1.X, p1.Y, z1, out float there) && IsStorey(there - z1) && !IsPastOutdoorDoorway(entry, i, p1)
                && !(cell.TrySampleFloor(p0.X, p0.Y, z0, out float here) && IsStorey(here - z0)))
            {
                return true;
            }
        }

        return false;

        static bool IsStorey(float rise) => rise >= -PhysicsConstants.StoreyBelow && rise <= PhysicsConstants.StoreyAbove;
    }

    /// <summary>Doors only: whether the mover already stands over the cell's floor (within the step height), so entering it crosses no wall.</summary>
    private static bool StartsOverFloor(LandblockEntry entry, int cellIndex, Vector2 p0, float z, float stepUp) =>
        entry.Cells[cellIndex].TrySampleFloor(p0.X, p0.Y, z, out float floorHere) && MathF.Abs(floorHere - z) <= stepUp;

    /// <summary>
    /// Doors only: the floor a move from <paramref name="p0"/> to <paramref name="p1"/> (landblock-local)
    /// reaches by passing in through the first portal to the outdoors it crosses (of the cells over the
    /// outdoor cells of p0 and p1), continued as an indoor move from that door's cell, so a door cell
    /// thinner than the move is passed, not mistaken for a wall. False when no door is crossed, the
    /// move ends on no floor beyond it, or that floor is more than the step height up.
    /// </summary>
    private bool TryEnterByDoor(LandblockEntry entry, Vector2 p0, Vector2 p1, float z, float stepUp, out int cellIndex, out float floorZ)
    {
        int doorCell = -1;
        float doorT = float.MaxValue;
        FirstDoor(entry, entry.EntryBuckets[OutdoorCellNumber(p0) - 1], p0, p1, z, stepUp, ref doorCell, ref doorT);
        FirstDoor(entry, entry.EntryBuckets[OutdoorCellNumber(p1) - 1], p0, p1, z, stepUp, ref doorCell, ref doorT);
        cellIndex = -1;
        floorZ = 0f;
        if (doorCell < 0)
        {
            return false;
        }

        int budget = PhysicsConstants.MaxCellVisits;
        Landing landing = FindLanding(entry, doorCell, p0, p1, z, stepUp, depth: 0, from: -1, tStart: doorT, falling: false, ref budget);
        if (landing.Kind != Arrival.Floor || landing.Z - z > stepUp)
        {
            return false;
        }

        cellIndex = landing.CellIndex;
        floorZ = landing.Z;
        return true;
    }

    /// <summary>The cell (among <paramref name="cells"/>) whose portal to the outdoors the move crosses inward first.</summary>
    private static void FirstDoor(LandblockEntry entry, int[] cells, Vector2 p0, Vector2 p1, float z, float stepUp, ref int doorCell, ref float doorT)
    {
        foreach (int i in cells)
        {
            ReadOnlySpan<PortalShape> shapes = entry.Cells[i].PortalShapes;
            int[] targets = entry.PortalTargets[i];
            for (int k = 0; k < shapes.Length; k++)
            {
                if (targets[k] != LandblockEntry.Outdoors || shapes[k].Kind != PortalKind.Vertical)
                {
                    continue;
                }

                float t = shapes[k].InwardCrossingFraction(p0, p1, z, stepUp);
                if (t >= 0f && t < doorT)
                {
                    doorCell = i;
                    doorT = t;
                }
            }
        }
    }

    private ResolveResult ResolveIndoor(Vector3 pos, uint cellId, Vector2 delta, float stepUp, in MovementOptions options, out bool rejected)
    {
        rejected = true;
        int lbX = CellIds.LandblockX(cellId), lbY = CellIds.LandblockY(cellId);
        LandblockEntry? entry = GetEntry(lbX, lbY);
        if (entry is null)
        {
            return new ResolveResult(pos, cellId, true); // held: the cell's landblock is not loaded
        }

        if (!entry.TryGetCellIndex(cellId, out int cellIndex))
        {
            throw new ArgumentException($"cell 0x{cellId:X8} is not registered in its landblock 0x{cellId | 0xFFFF:X8}.", "currentCellId");
        }

        Vector2 p0 = Representable(lbX, lbY, new Vector2(pos.X, pos.Y) - Origin2(lbX, lbY));
        Vector2 p1 = Representable(lbX, lbY, p0 + delta);
        int budget = PhysicsConstants.MaxCellVisits;
        Landing landing = FindLanding(entry, cellIndex, p0, p1, pos.Z, stepUp, depth: 0, from: -1, tStart: 0f, falling: false, ref budget);
        CellSurface cell = entry.Cells[cellIndex];
        switch (landing.Kind)
        {
            case Arrival.Floor when !IsStepTooHigh(cell, p0, pos.Z, landing.Z, stepUp):
                rejected = false;
                return Land(ToWorld(lbX, lbY, p1, landing.Z), pos.Z, entry.Cells[landing.CellIndex].CellId, in options);
            case Arrival.Outdoors when !IsStepTooHigh(cell, p0, pos.Z, landing.Z, stepUp)
                && !(options.WalkableSlope && landing.Z > pos.Z && GetEntry(landing.OutdoorX, landing.OutdoorY)!.Terrain
                    .NormalZUnchecked(landing.OutdoorLocal.X, landing.OutdoorLocal.Y) < PhysicsConstants.FloorZ):
                rejected = false;
                return Land(
                    ToWorld(landing.OutdoorX, landing.OutdoorY, landing.OutdoorLocal, landing.Z),
                    pos.Z,
                    OutdoorCellId(landing.OutdoorX, landing.OutdoorY, landing.OutdoorLocal),
                    in options);
            default:
                // Rejected (wall, missing cell, unloaded land, step too high), or nothing under the
                // mover at all: it stays, on its own cell's floor if it is at (or below) it.
                return Refuse(lbX, lbY, p0, pos.Z, cell.TrySampleFloor(p0.X, p0.Y, pos.Z, out float floorHere) ? floorHere : null, cellId, in options);
        }
    }

    /// <summary>
    /// Where a move from p0 to p1 inside cell <paramref name="cellIndex"/> ends: through the first
    /// doorway it crosses, else on this cell's floor, else through a floor opening under p1, else
    /// (first cell only) on a portal neighbour's floor under p1.
    /// </summary>
    private Landing FindLanding(LandblockEntry entry, int cellIndex, Vector2 p0, Vector2 p1, float z, float stepUp, int depth, int from, float tStart, bool falling, ref int budget)
    {
        if (--budget < 0)
        {
            return Landing.Blocked; // the call's search has visited as many cells as any real move needs
        }

        CellSurface cell = entry.Cells[cellIndex];
        ReadOnlySpan<PortalShape> shapes = cell.PortalShapes;
        int[] targets = entry.PortalTargets[cellIndex];

        int doorway = -1;
        float doorwayT = float.MaxValue;
        bool throughWall = false;
        for (int k = 0; k < shapes.Length; k++)
        {
            if (shapes[k].Kind != PortalKind.Vertical || (targets[k] == from && from >= 0))
            {
                continue;
            }

            float t = shapes[k].CrossingFraction(p0, p1, z, stepUp, out bool crossesPlane);
            throughWall |= crossesPlane && t < 0f;
            if (t >= tStart && t < doorwayT)
            {
                doorway = k;
                doorwayT = t;
            }
        }

        if (doorway >= 0)
        {
            Landing through = Pass(entry, cellIndex, targets[doorway], p0, p1, z, stepUp, depth, doorwayT, falling: false, ref budget);
            return through.Kind == Arrival.Nothing ? Landing.Blocked : through;
        }

        if (cell.TrySampleFloor(p1.X, p1.Y, z, out float floorZ))
        {
            return Landing.OnFloor(cellIndex, floorZ);
        }

        for (int k = 0; k < shapes.Length; k++)
        {
            PortalShape shape = shapes[k];
            if (shape.Kind != PortalKind.Horizontal || (targets[k] == from && from >= 0) || !shape.ContainsXY(p1.X, p1.Y))
            {
                continue;
            }

            float planeZ = shape.PlaneZ(p1.X, p1.Y);
            if (planeZ > z + stepUp + PhysicsConstants.EdgeTolerance || (!falling && planeZ < z - stepUp - PhysicsConstants.EdgeTolerance))
            {
                continue; // an opening overhead, or one this mover is not standing at
            }

            Landing through = Pass(entry, cellIndex, targets[k], p0, p1, z, stepUp, depth, tStart, falling: true, ref budget);
            if (through.Kind != Arrival.Nothing)
            {
                return through;
            }
        }

        if (depth == 0 && !throughWall)
        {
            // Portal geometry decided nothing: any portal neighbour with a floor under p1 takes the
            // mover. Not when the move passed a doorway's plane beside its opening: that is the wall.
            int best = -1;
            float bestZ = 0f, bestDistance = float.MaxValue;
            foreach (int target in targets)
            {
                if (target >= 0 && entry.Cells[target].TrySampleFloor(p1.X, p1.Y, z, out float neighbourZ)
                    && MathF.Abs(neighbourZ - z) < bestDistance)
                {
                    best = target;
                    bestZ = neighbourZ;
                    bestDistance = MathF.Abs(neighbourZ - z);
                }
            }

            if (best >= 0)
            {
                return Landing.OnFloor(best, bestZ);
            }
        }

        return Landing.Nothing;
    }

    /// <summary>The landing beyond a portal of cell <paramref name="cellIndex"/> leading to <paramref name="target"/>.</summary>
    private Landing Pass(LandblockEntry entry, int cellIndex, int target, Vector2 p0, Vector2 p1, float z, float stepUp, int depth, float t, bool falling, ref int budget)
    {
        if (target == LandblockEntry.Missing || depth >= PhysicsConstants.MaxPortalHops)
        {
            return Landing.Blocked;
        }

        if (target == LandblockEntry.Outdoors)
        {
            Vector2 local = p1;
            int x = entry.X, y = entry.Y;
            Wrap(ref local.X, ref x);
            Wrap(ref local.Y, ref y);
            LandblockEntry? land = GetEntry(x, y);
            return land is null
                ? Landing.Blocked
                : Landing.OnTerrain(x, y, local, land.Terrain.SampleZUnchecked(local.X, local.Y));
        }

        return FindLanding(entry, target, p0, p1, z, stepUp, depth + 1, cellIndex, t, falling, ref budget);
    }

    /// <summary>
    /// Outdoor entry: the floor, among the cells over the candidate's outdoor cell, nearest the
    /// ground the mover would stand on there (<paramref name="z"/>, the terrain's Z) and within the
    /// step height of it (above or below); ties go to the lower cell id. Measuring from the ground
    /// there, not from the feet before the move, makes the answer the same when the mover stands
    /// still at the end point.
    /// A floor point on or past one of the cell's doorways to the outdoors is outdoors: that is where
    /// a mover leaving by the door lands, so it must not be taken back in by standing still.
    /// </summary>
    private static bool TryEnterCell(LandblockEntry entry, Vector2 p, float z, float stepUp, out int cellIndex, out float floorZ)
    {
        cellIndex = -1;
        floorZ = 0f;
        float bestDistance = float.MaxValue;
        foreach (int i in entry.EntryBuckets[OutdoorCellNumber(p) - 1])
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
            if (targets[k] == LandblockEntry.Outdoors && shapes[k].Kind == PortalKind.Vertical && shapes[k].HorizontalDistance(p) > -PhysicsConstants.EdgeTolerance)
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>
    /// A rise is too high when it is more than the step height above the mover's Z, and above the
    /// floor under the mover too where the mover has sunk below that floor (so a mover placed under
    /// its floor can walk out instead of being stuck). The floor is sampled only on that rare path.
    /// </summary>
    private static bool IsStepTooHigh(CellSurface cell, Vector2 p0, float z, float newZ, float stepUp) =>
        newZ - z > stepUp
        && (!cell.TrySampleFloor(p0.X, p0.Y, z, out float floorHere) || newZ - MathF.Max(z, floorHere) > stepUp);

    private static void Validate(Vector3 pos, uint cellId, Vector3 delta, float stepUp)
    {
        if (!IsFinite(pos))
        {
            throw new ArgumentException($"currentPos {pos} must be finite.", "currentPos");
        }

        if (!IsFinite(delta))
        {
            throw new ArgumentException($"delta {delta} must be finite.", nameof(delta));
        }

        if (!float.IsFinite(stepUp) || stepUp < 0f)
        {
            throw new ArgumentOutOfRangeException("stepUpHeight", stepUp, "stepUpHeight must be a finite height ≥ 0 m.");
        }

        uint low = cellId & 0xFFFF;
        if ((low > PhysicsConstants.CellsPerSide * PhysicsConstants.CellsPerSide && low < CellIds.FirstIndoor) || low > CellIds.LastIndoor)
        {
            throw new ArgumentException($"currentCellId 0x{cellId:X8} is not a cell: outdoor cells are 0x0001..0x0040, indoor 0x0100..0xFFFD.", "currentCellId");
        }

        if (!CellIds.IsInWorld(CellIds.LandblockX(cellId), CellIds.LandblockY(cellId)))
        {
            throw new ArgumentException(
                $"currentCellId 0x{cellId:X8} names a landblock off the world: X and Y must be within 0x00..0x{PhysicsConstants.MaxLandblockIndex:X2}.", "currentCellId");
        }
    }

    private static bool IsFinite(Vector3 v) => float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z);

    /// <summary>
    /// The landblock an outdoor mover is resolved from, and its landblock-local position: the one its
    /// cell id names when the position is within <see cref="SeamSlack"/> of it, else the one under the position.
    /// </summary>
    private void Locate(Vector3 pos, uint cellId, out int lbX, out int lbY, out Vector2 local)
    {
        if ((cellId & 0xFFFF) != 0)
        {
            lbX = CellIds.LandblockX(cellId);
            lbY = CellIds.LandblockY(cellId);
            local = Representable(lbX, lbY, new Vector2(pos.X, pos.Y) - Origin2(lbX, lbY));
            if (local.X >= -SeamSlack && local.Y >= -SeamSlack
                && local.X <= PhysicsConstants.LandblockSize + SeamSlack && local.Y <= PhysicsConstants.LandblockSize + SeamSlack)
            {
                return;
            }
        }

        lbX = _originX;
        lbY = _originY;
        local = new Vector2(pos.X, pos.Y);
        Wrap(ref local.X, ref lbX);
        Wrap(ref local.Y, ref lbY);
        local = Representable(lbX, lbY, local);
    }

    /// <summary>
    /// The landblock-local point that survives the round trip to the world frame: the local value of
    /// the world position it is returned as. Every surface is sampled here, so the returned position
    /// is exactly where the answer was computed, and resolving it again finds the same ground.
    /// </summary>
    private Vector2 Representable(int lbX, int lbY, Vector2 local)
    {
        Vector2 origin = Origin2(lbX, lbY);
        return (origin + local) - origin;
    }

    /// <summary>
    /// Moves a landblock-local coordinate into 0 ≤ c &lt; 192, stepping the landblock index to match.
    /// Exact: subtracting a multiple of 192 from a float in the adjacent range loses nothing.
    /// </summary>
    private static void Wrap(ref float coordinate, ref int landblock)
    {
        if (coordinate >= 0f && coordinate < PhysicsConstants.LandblockSize)
        {
            return;
        }

        double steps = Math.Floor(coordinate / (double)PhysicsConstants.LandblockSize);
        steps = Math.Clamp(steps, -2 * WorldSide, 2 * WorldSide); // far off the world; stays off it
        coordinate = (float)(coordinate - (steps * PhysicsConstants.LandblockSize));
        landblock += (int)steps;
        if (coordinate >= PhysicsConstants.LandblockSize)
        {
            coordinate -= PhysicsConstants.LandblockSize; // rounding put it on the far seam
            landblock++;
        }
    }

    private LandblockEntry? GetEntry(int x, int y) =>
        CellIds.IsInWorld(x, y) ? _landblocks[CellIds.LandblockIndex(x, y)] : null;

    private static float Offset(int landblock, int origin) => (landblock - origin) * PhysicsConstants.LandblockSize;

    private Vector2 Origin2(int lbX, int lbY) => new(Offset(lbX, _originX), Offset(lbY, _originY));

    private Vector3 ToWorld(int lbX, int lbY, Vector2 local, float z) =>
        new(Offset(lbX, _originX) + local.X, Offset(lbY, _originY) + local.Y, z);

    /// <summary>
    /// The full id of the outdoor cell at <paramref name="local"/> of landblock (lbX, lbY). A mover held
    /// off the world (a position beyond its edge) gets the nearest edge cell of the world, never a
    /// wrapped-around prefix of another landblock.
    /// </summary>
    private static uint OutdoorCellId(int lbX, int lbY, Vector2 local)
    {
        if (!CellIds.IsInWorld(lbX, lbY))
        {
            ClampToWorld(ref lbX, ref local.X);
            ClampToWorld(ref lbY, ref local.Y);
        }

        return CellIds.Prefix(lbX, lbY) | OutdoorCellNumber(local);

        static void ClampToWorld(ref int landblock, ref float coordinate)
        {
            if (landblock < 0)
            {
                (landblock, coordinate) = (0, 0f);
            }
            else if (landblock > PhysicsConstants.MaxLandblockIndex)
            {
                (landblock, coordinate) = (PhysicsConstants.MaxLandblockIndex, PhysicsConstants.LandblockSize);
            }
        }
    }

    private static uint OutdoorCellNumber(Vector2 local)
    {
        int cx = (int)Math.Clamp(local.X / PhysicsConstants.CellSize, 0f, PhysicsConstants.CellsPerSide - 1);
        int cy = (int)Math.Clamp(local.Y / PhysicsConstants.CellSize, 0f, PhysicsConstants.CellsPerSide - 1);
        return (uint)((cx * PhysicsConstants.CellsPerSide) + cy + 1);
    }

    private enum Arrival
    {
        /// <summary>No surface found.</summary>
        Nothing,

        /// <summary>A wall, a missing cell or unloaded land is in the way.</summary>
        Blocked,

        /// <summary>On a cell's floor.</summary>
        Floor,

        /// <summary>On terrain, through a portal to the outdoors.</summary>
        Outdoors,
    }

    private readonly record struct Landing(Arrival Kind, int CellIndex, float Z, int OutdoorX, int OutdoorY, Vector2 OutdoorLocal)
    {
        public static Landing Nothing => default;

        public static Landing Blocked => new(Arrival.Blocked, -1, 0f, 0, 0, default);

        public static Landing OnFloor(int cellIndex, float z) => new(Arrival.Floor, cellIndex, z, 0, 0, default);

        public static Landing OnTerrain(int x, int y, Vector2 local, float z) => new(Arrival.Outdoors, -1, z, x, y, local);
    }
}
