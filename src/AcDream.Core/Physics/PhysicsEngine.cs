using System.Numerics;
using System.Runtime.CompilerServices;

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
/// the float spacing at its magnitude (about 4 mm at the far corner of the global frame), and the
/// answer is computed at that rounded position.
/// </para>
/// <para>
/// Threads: any number of threads may call <c>Resolve</c> (and the other queries) at the same time,
/// and one writer thread may call <see cref="AddLandblock"/> and <see cref="RemoveLandblock"/> while
/// they do. Each landblock is published whole, in one reference write, and never changed afterwards,
/// so a resolver sees it either wholly before or wholly after a change, never half of one: one call
/// reads each landblock once. (A move across a seam reads two landblocks, each whole, possibly one
/// from before and one from after a change made during the call; a swept move is a series of such
/// moves, each reading afresh, so a change can fall between two of its sub-steps.) Resolving takes
/// no lock and allocates nothing.
/// </para>
/// <para>
/// This class is a facade: the landblock registry (<c>LandblockRegistry</c>), the world frame
/// (<c>WorldFrame</c>), outdoor resolution (<c>OutdoorResolver</c>), indoor resolution
/// (<c>IndoorResolver</c>) and the portal search (<c>PortalTraversal</c>) are internal types, each
/// one concern; <c>docs/physics.md</c> maps them.
/// </para>
/// </remarks>
public sealed class PhysicsEngine
{
    private readonly LandblockRegistry _registry = new();
    private readonly WorldFrame _frame;
    private readonly OutdoorResolver _outdoor;
    private readonly IndoorResolver _indoor;
    private readonly BodyPlanner _body;

    /// <summary>An engine whose world frame is global: world = landblock X·192 + landblock-local metres.</summary>
    public PhysicsEngine()
        : this(new WorldFrame(0, 0))
    {
    }

    /// <summary>
    /// An engine whose world frame is centred on a landblock: world (0, 0) is the south-west corner
    /// of <paramref name="centerLandblockId"/>, so world = (X − centreX)·192 + landblock-local metres.
    /// </summary>
    /// <param name="centerLandblockId">The centre landblock, <c>0xXXYYFFFF</c> or <c>0xXXYY0000</c>.</param>
    /// <exception cref="ArgumentException">The id is not a landblock id of the world.</exception>
    public PhysicsEngine(uint centerLandblockId)
        : this(new WorldFrame(CheckedCentre(centerLandblockId).X, CheckedCentre(centerLandblockId).Y))
    {
    }

    private PhysicsEngine(WorldFrame frame)
    {
        _frame = frame;
        var portals = new PortalTraversal(_registry);
        _outdoor = new OutdoorResolver(_registry, frame, portals);
        _indoor = new IndoorResolver(_registry, frame, portals);
        _body = new BodyPlanner(_registry, frame);
    }

    /// <summary>Number of registered landblocks.</summary>
    public int LandblockCount => _registry.Count;

    /// <summary>Whether a landblock (any low 16 bits) is registered.</summary>
    public bool ContainsLandblock(uint landblockId) =>
        _registry.Get(CellIds.LandblockX(landblockId), CellIds.LandblockY(landblockId)) is not null;

    /// <summary>
    /// World position (metres, Z = 0) of the south-west corner of a landblock: add landblock-local
    /// coordinates to it to get world coordinates.
    /// </summary>
    /// <param name="landblockId">Any id of the landblock (its low 16 bits are ignored).</param>
    public Vector3 GetLandblockOrigin(uint landblockId) => new(_frame.Origin(CellIds.LandblockX(landblockId), CellIds.LandblockY(landblockId)), 0f);

    /// <summary>The landblock (<c>0xXXYYFFFF</c>) under a world position, metres; positions off the world clamp to its nearest edge.</summary>
    /// <exception cref="ArgumentException">A coordinate is NaN.</exception>
    public uint LandblockAt(Vector3 worldPosition)
    {
        if (float.IsNaN(worldPosition.X) || float.IsNaN(worldPosition.Y))
        {
            throw new ArgumentException($"world position {worldPosition} must not be NaN.", nameof(worldPosition));
        }

        return _frame.LandblockAt(worldPosition);
    }

    /// <summary>A landblock-local position (metres) of the landblock of <paramref name="id"/> (any id of it), in world metres.</summary>
    public Vector3 ToWorld(uint id, Vector3 landblockLocal) => GetLandblockOrigin(id) + landblockLocal;

    /// <summary>A world position (metres) in the landblock-local frame of the landblock of <paramref name="id"/> (any id of it).</summary>
    public Vector3 ToLandblockLocal(uint id, Vector3 world) => world - GetLandblockOrigin(id);

    /// <summary>
    /// The ground under a world position: for an outdoor <paramref name="cellId"/> (or 0) the terrain
    /// of the landblock under the position; for an indoor one, that cell's floor nearest the position's
    /// Z. The same surfaces, sampled the same way, as <c>Resolve</c>.
    /// </summary>
    /// <param name="worldPosition">World metres; Z is the reference for stacked floors.</param>
    /// <param name="cellId">The cell the position is in (<c>0xXXYYCCCC</c>), or an outdoor id / 0 for the terrain.</param>
    /// <param name="groundZ">The ground's Z, metres.</param>
    /// <param name="normal">The ground's unit normal (pointing up).</param>
    /// <returns>False when the landblock is not loaded, the cell is unknown, or no floor of the cell lies under the position.</returns>
    /// <exception cref="ArgumentException">A coordinate is not finite.</exception>
    public bool TryGetGround(Vector3 worldPosition, uint cellId, out float groundZ, out Vector3 normal)
    {
        if (!IsFinite(worldPosition))
        {
            throw new ArgumentException($"world position {worldPosition} must be finite.", nameof(worldPosition));
        }

        (groundZ, normal) = (0f, default);
        if (CellIds.IsIndoor(cellId))
        {
            int x = CellIds.LandblockX(cellId), y = CellIds.LandblockY(cellId);
            if (_registry.Get(x, y) is not LandblockEntry entry || !entry.TryGetCellIndex(cellId, out int index))
            {
                return false;
            }

            Vector2 p = _frame.Representable(x, y, new Vector2(worldPosition.X, worldPosition.Y) - _frame.Origin(x, y));
            return entry.Cells[index].TrySampleFloor(p.X, p.Y, worldPosition.Z, out groundZ, out normal);
        }

        _frame.Locate(worldPosition, cellId, out int lbX, out int lbY, out Vector2 local);
        if (_registry.Get(lbX, lbY) is not LandblockEntry land)
        {
            return false;
        }

        groundZ = land.Terrain.SampleZUnchecked(local.X, local.Y);
        normal = land.Terrain.NormalUnchecked(local.X, local.Y);
        return true;
    }

    /// <summary>
    /// Register terrain + EnvCell surfaces for a loaded landblock.
    /// </summary>
    /// <remarks>
    /// Registering a landblock that is already registered replaces it. Every argument is checked
    /// and the landblock's lookups are built before anything changes: on an exception the engine is as
    /// it was. The landblock is published in one step, so threads resolving meanwhile see it wholly
    /// before or wholly after (see the class remarks). One writer thread at a time.
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

        _registry.Set(new LandblockEntry(CellIds.LandblockX(landblockId), CellIds.LandblockY(landblockId), terrain, sorted));
    }

    /// <summary>Remove all surfaces for an unloaded landblock.</summary>
    /// <remarks>Any low 16 bits are accepted. Removing a landblock that is not registered does nothing, so an unload path may call it unconditionally. One writer thread at a time; resolvers may run meanwhile.</remarks>
    public void RemoveLandblock(uint landblockId) =>
        _registry.Remove(CellIds.LandblockX(landblockId), CellIds.LandblockY(landblockId));

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
        MoveQuery.Validate(currentPos, currentCellId, delta, stepUpHeight);
        MovementOptions none = default; // no effects: the spec's engine
        var query = new MoveQuery(currentPos, currentCellId, new Vector2(delta.X, delta.Y), stepUpHeight, in none);
        return Step(ref query);
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
        MoveQuery.Validate(currentPos, currentCellId, delta, stepUpHeight);
        var move = new Vector2(delta.X, delta.Y);
        if (options.Body is MoverBody body && (move == Vector2.Zero || !_body.IsOpenGround(currentPos, currentCellId, move, body)))
        {
            return ResolveWithBody(currentPos, currentCellId, move, stepUpHeight, in options, contourLeft: true);
        }

        // No body, or a body on open ground (no wall in its reach): the point move is the answer.
        ResolveResult result = PointMove(currentPos, currentCellId, move, stepUpHeight, in options);
        return result.Outcome == ResolveOutcome.SlopeTooSteep && options.Body.HasValue && options.WalkableSlope
            ? AlongContour(currentPos, currentCellId, move, stepUpHeight, in options, result)
            : result;
    }

    /// <summary>A point's move: swept in sub-steps when <see cref="MovementOptions.SweepStepLength"/> asks, else one step.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)] // Resolve's own path: the same code as before it was shared with the body's
    private ResolveResult PointMove(Vector3 pos, uint cellId, Vector2 move, float stepUp, in MovementOptions options)
    {
        if (options.SweepStepLength is float sweep && move.LengthSquared() > sweep * sweep)
        {
            return Sweep(pos, cellId, move, stepUp, in options, sweep);
        }

        var query = new MoveQuery(pos, cellId, move, stepUp, in options);
        return Step(ref query);
    }

    /// <summary>
    /// The body's move: its path among the walls (<see cref="BodyPlanner"/>), walked leg by leg as
    /// point moves, so floors, cells, steps and doorways are decided as for a point. A path with no
    /// contact is the point move itself (swept, its sub-steps aimed as a leg's: see <see cref="Leg"/>).
    /// With walkable slope, a leg refused as too steep slides along the slope's contour once
    /// (<paramref name="contourLeft"/>).
    /// </summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // kept out of Resolve, so a call without a body pays nothing for it
    [SkipLocalsInit] // the path's points are written before they are read
    private ResolveResult ResolveWithBody(Vector3 pos, uint cellId, Vector2 move, float stepUp, in MovementOptions options, bool contourLeft)
    {
        Span<Vector2> points = stackalloc Vector2[PhysicsConstants.MaxBodyContacts + 2];
        var path = default(BodySweep.Path);
        int lbX = 0, lbY = 0;
        bool planned = move != Vector2.Zero && _body.Plan(pos, cellId, move, stepUp, options.Body!.Value, points, ref path, out lbX, out lbY);
        if (!planned || path.Contacts == 0)
        {
            // Free: the point move itself; a swept one aims each sub-step at its point of the path (see Leg).
            ResolveResult free = planned && options.SweepStepLength is float sweep && move.LengthSquared() > sweep * sweep
                ? Leg(pos, cellId, points[0], points[1], _frame.Origin(lbX, lbY), pos.Z, stepUp, in options)
                : PointMove(pos, cellId, move, stepUp, in options);
            // Not planned for a real move: no land under the mover, so no ceiling to check at the end.
            if (!free.IsRefused && (planned || move == Vector2.Zero) && LowCeiling(in free, pos.Z, stepUp, in options, out Vector3 ceiling))
            {
                return Stopped(pos, cellId, stepUp, in options, ceiling);
            }

            return contourLeft && free.Outcome == ResolveOutcome.SlopeTooSteep && options.WalkableSlope
                ? AlongContour(pos, cellId, move, stepUp, in options, free)
                : free;
        }

        var wall = new Vector3(path.Normal.X, path.Normal.Y, 0f);
        if (path.Count == 1)
        {
            return Stopped(pos, cellId, stepUp, in options, wall);
        }

        ResolveResult result = default;
        Vector3 at = pos;
        uint cell = cellId;
        Vector2 origin = _frame.Origin(lbX, lbY);
        for (int i = 1; i < path.Count; i++)
        {
            ResolveResult next = Leg(at, cell, points[i - 1], points[i], origin, pos.Z, stepUp, in options);
            if (next.IsRefused)
            {
                if (contourLeft && next.Outcome == ResolveOutcome.SlopeTooSteep && options.WalkableSlope)
                {
                    return AlongContour(at, cell, points[i] - (new Vector2(at.X, at.Y) - origin), stepUp, in options, next);
                }

                return i == 1 ? next : result with { Outcome = next.Outcome, SurfaceNormal = next.SurfaceNormal };
            }

            (result, at, cell) = (next, next.Position, next.CellId);
        }

        if (result.Outcome != ResolveOutcome.Moved)
        {
            return result;
        }

        // A path whose corners the world frame rounds back onto the start (a body at rest against a corner,
        // far from the origin) did not slide: it is stopped.
        bool stayed = result.Position.X == pos.X && result.Position.Y == pos.Y;
        return result with { Outcome = stayed ? ResolveOutcome.Wall : ResolveOutcome.Slid, SurfaceNormal = wall };
    }

    /// <summary>
    /// One leg of a body's path, <paramref name="from"/> → <paramref name="to"/> (landblock-local to
    /// <paramref name="origin"/>), as a point move: in equal sub-steps when
    /// <see cref="MovementOptions.SweepStepLength"/> asks, stopping at the first refused one as
    /// <see cref="Sweep"/> does. Each sub-step aims at its point of the leg from wherever the last answer
    /// was rounded to, so the world frame's rounding of one sub-step or corner is not carried into the
    /// next: it piled up past the body's skin at the far corner of the global frame (a 2 m slide in five
    /// sub-steps ended 3.7 mm into the wall; 5 m moves ended centimetres off their paths).
    /// </summary>
    private ResolveResult Leg(Vector3 at, uint cell, Vector2 from, Vector2 to, Vector2 origin, float planZ, float stepUp, in MovementOptions options)
    {
        Vector2 leg = to - from;
        int steps = options.SweepStepLength is float sweep && leg.LengthSquared() > sweep * sweep
            ? (int)Math.Min(Math.Ceiling(leg.Length() / (double)sweep), PhysicsConstants.MaxSweepSteps)
            : 1;
        ResolveResult result = default;
        for (int k = 1; k <= steps; k++)
        {
            Vector2 target = k == steps ? to : from + (leg * ((float)k / steps));
            var query = new MoveQuery(at, cell, target - (new Vector2(at.X, at.Y) - origin), stepUp, in options);
            ResolveResult next = Step(ref query);
            if (next.IsRefused)
            {
                return k == 1 ? next : result with { Outcome = next.Outcome, SurfaceNormal = next.SurfaceNormal };
            }

            if (LowCeiling(in next, planZ, stepUp, in options, out Vector3 ceiling))
            {
                return k == 1 ? Stopped(at, cell, stepUp, in options, ceiling) : result with { Outcome = ResolveOutcome.Wall, SurfaceNormal = ceiling };
            }

            (result, at, cell) = (next, next.Position, next.CellId);
        }

        return result;
    }

    /// <summary>
    /// Whether a body that has stepped up to <paramref name="next"/> (its feet above
    /// <paramref name="planZ"/>, where its path was planned) meets a wall or ceiling in its height band
    /// there: a doorway lower than the body above the floor it would stand on stops it, where the band of
    /// the feet it set out with let it under the lintel (the player, 1.835 m tall, stepped up into the
    /// cottage's 1.8 m door cells and stood there with its head in the wall). <paramref name="normal"/>:
    /// out of the deepest such wall, seen from above.
    /// </summary>
    private bool LowCeiling(in ResolveResult next, float planZ, float stepUp, in MovementOptions options, out Vector3 normal)
    {
        normal = default;
        if (!(next.Position.Z > planZ + PhysicsConstants.GroundTolerance)
            || !(_body.Overlap(next.Position, next.CellId, stepUp, options.Body!.Value, out Vector2 outward) > 0f))
        {
            return false;
        }

        normal = new Vector3(outward.X, outward.Y, 0f);
        return true;
    }

    /// <summary>A body stopped where it is by a wall of normal <paramref name="wall"/>: <see cref="Stay"/>, reported as a wall.</summary>
    private ResolveResult Stopped(Vector3 pos, uint cellId, float stepUp, in MovementOptions options, Vector3 wall)
    {
        ResolveResult stay = Stay(pos, cellId, stepUp, in options);
        return stay.Outcome == ResolveOutcome.Moved ? stay with { Outcome = ResolveOutcome.Wall, SurfaceNormal = wall } : stay;
    }

    /// <summary>
    /// Walkable slope with a body: <paramref name="refused"/> was too steep to climb; the move goes on
    /// with its uphill part taken out (along the slope's contour), or the refusal stands.
    /// </summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // kept out of Resolve: rare, and only with a body
    private ResolveResult AlongContour(Vector3 pos, uint cellId, Vector2 move, float stepUp, in MovementOptions options, ResolveResult refused)
    {
        var downhill = new Vector2(refused.SurfaceNormal.X, refused.SurfaceNormal.Y);
        float length = downhill.Length();
        if (length == 0f)
        {
            return refused;
        }

        downhill /= length;
        float uphill = -Vector2.Dot(move, downhill);
        Vector2 contour = uphill > 0f ? move + (downhill * uphill) : move;
        if (contour.LengthSquared() < PhysicsConstants.ContactTolerance * PhysicsConstants.ContactTolerance)
        {
            return refused;
        }

        ResolveResult along = _body.IsOpenGround(pos, cellId, contour, options.Body!.Value)
            ? PointMove(pos, cellId, contour, stepUp, in options)
            : ResolveWithBody(pos, cellId, contour, stepUp, in options, contourLeft: false);
        return along.IsRefused
            ? refused
            : along with { Outcome = ResolveOutcome.Slid, SurfaceNormal = refused.SurfaceNormal };
    }

    /// <summary>
    /// A body stopped at once by a wall stays where it is: the answer of not moving, with the refusal
    /// ground rule (<see cref="Answers.Refuse"/>): without step down, feet more than the ground tolerance
    /// above the ground stay in the air.
    /// </summary>
    private ResolveResult Stay(Vector3 pos, uint cellId, float stepUp, in MovementOptions options)
    {
        ResolveResult stay = PointMove(pos, cellId, Vector2.Zero, stepUp, in options);
        return options.StepDownHeight is null && stay.IsOnGround && stay.Outcome == ResolveOutcome.Moved
            && pos.Z - stay.Position.Z > PhysicsConstants.GroundTolerance
            ? stay with { Position = stay.Position with { Z = pos.Z }, IsOnGround = false }
            : stay;
    }

    /// <summary>Equal sub-steps no longer than <paramref name="sweep"/>, stopping at the first refused one, whose outcome the answer reports.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // kept out of Resolve: its queries would be zeroed on every call, swept or not
    private ResolveResult Sweep(Vector3 pos, uint cellId, Vector2 move, float stepUp, in MovementOptions options, float sweep)
    {
        int steps = (int)Math.Min(Math.Ceiling(move.Length() / (double)sweep), PhysicsConstants.MaxSweepSteps);
        Vector2 step = move / steps;
        var query = new MoveQuery(pos, cellId, step, stepUp, in options);
        ResolveResult result = Step(ref query);
        for (int i = 1; i < steps && !result.IsRefused; i++)
        {
            query = new MoveQuery(result.Position, result.CellId, step, stepUp, in options);
            ResolveResult next = Step(ref query);
            result = next.IsRefused ? result with { Outcome = next.Outcome, SurfaceNormal = next.SurfaceNormal } : next;
        }

        return result;
    }

    /// <summary>One move, end-point checked.</summary>
    private ResolveResult Step(ref MoveQuery query) =>
        CellIds.IsIndoor(query.CellId) ? _indoor.Resolve(ref query) : _outdoor.Resolve(ref query);

    private static bool IsFinite(Vector3 v) => float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z);

    private static (int X, int Y) CheckedCentre(uint centerLandblockId)
    {
        CellIds.ValidateLandblockId(centerLandblockId, nameof(centerLandblockId));
        return (CellIds.LandblockX(centerLandblockId), CellIds.LandblockY(centerLandblockId));
    }
}
