using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.Point;
using AcDream.Core.Physics.Body;

namespace AcDream.Core.Physics;

/// <summary>
/// The engine: owns the registered landblocks (terrain, indoor cells and objects) and answers where a
/// mover ends up (<c>Resolve</c>) and what ground lies under a position.
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
/// and one writer thread may call <see cref="AddLandblock(uint, TerrainSurface, IReadOnlyList{CellSurface})"/> and <see cref="RemoveLandblock"/> while
/// they do. Each landblock is published whole, in one reference write, and never changed afterwards,
/// so a resolver sees it either wholly before or wholly after a change, never half of one: one call
/// reads each landblock once. (A move across a seam reads two landblocks, each whole, possibly one
/// from before and one from after a change made during the call; a swept move is a series of such
/// moves, each reading afresh, so a change can fall between two of its sub-steps.) Resolving takes
/// no lock and allocates nothing.
/// </para>
/// <para>
/// This class is a facade: the landblock registry (<c>LandblockRegistry</c>), the world frame
/// (<c>WorldFrame</c>), a point's move (<c>PointMover</c>: outdoor resolution, <c>OutdoorResolver</c>;
/// indoor resolution, <c>IndoorResolver</c>; the portal search, <c>PortalTraversal</c>) and the body's
/// (<c>BodyResolver</c>, <c>BodyPlanner</c>) are internal types, each one concern;
/// <c>docs/physics.md</c> maps them. The host queries (frames, the ground) are in
/// <c>PhysicsEngine.Queries.cs</c>; the call that also reports what a move met in <c>PhysicsEngine.Report.cs</c>.
/// </para>
/// </remarks>
public sealed partial class PhysicsEngine
{
    private readonly LandblockRegistry _registry = new();
    private readonly WorldFrame _frame;
    private readonly PointMover _point;
    private readonly BodyPlanner _planner;
    private readonly BodyMotion _motion;
    private readonly MoverRegistry _movers;

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
        var portals = new PortalTraversal();
        _point = new PointMover(new OutdoorResolver(frame, portals), new IndoorResolver(frame, portals));
        _planner = new BodyPlanner(frame);
        _motion = new BodyMotion(frame, _point, new BodyResolver(_planner, frame, _point), _planner);
        _movers = new MoverRegistry(frame, MoverSolid.StandsIn);
    }

    /// <summary>
    /// The things that move (creatures, players, doors), in this engine's world frame: register, move and remove them
    /// here, and <see cref="MoverRegistry.Commit"/> each frame; every <c>Resolve</c> meets the state last committed.
    /// </summary>
    public MoverRegistry Movers => _movers;

    /// <summary>Number of registered landblocks.</summary>
    public int LandblockCount => _registry.Count;

    /// <summary>Whether a landblock (any low 16 bits) is registered.</summary>
    public bool ContainsLandblock(uint landblockId) =>
        _registry.Get(CellIds.LandblockX(landblockId), CellIds.LandblockY(landblockId)) is not null;

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
        IReadOnlyList<CellSurface> cells) => AddLandblock(landblockId, terrain, cells, []);

    /// <summary>
    /// Register terrain, EnvCell surfaces and the objects of a loaded landblock (see
    /// <see cref="ObjectSurface"/>): objects with <see cref="ObjectSurface.CellId"/> 0 stand outdoors,
    /// the others in their cell. With no objects, exactly the three-argument call.
    /// </summary>
    /// <remarks>
    /// As the three-argument call: checked and built before anything changes, published in one step.
    /// A building shell marks its door cells, and every cell reached from them through portals, as
    /// shelled: entering them from outdoors is then decided by the shell's walls and openings, and the
    /// doors-only rule no longer applies to them.
    /// </remarks>
    /// <param name="landblockId">The landblock, <c>0xXXYYFFFF</c> or <c>0xXXYY0000</c>.</param>
    /// <param name="terrain">Its terrain.</param>
    /// <param name="cells">Its indoor cells (may be empty).</param>
    /// <param name="objects">Its objects (may be empty), landblock-local.</param>
    /// <exception cref="ArgumentNullException">An argument, a cell or an object is null.</exception>
    /// <exception cref="ObjectRefusedException">One object breaks a rule (its index, id and rule named): it stands in a cell that is not among <paramref name="cells"/>, a building's door cell is not among them, or an outdoor object reaches more than <see cref="PhysicsConstants.MaxSeamReach"/> past the landblock.</exception>
    /// <exception cref="ArgumentException">As the three-argument call; or more than <see cref="PhysicsConstants.MaxOutdoorObjects"/> objects stand outdoors, or a building's walls reach more than <see cref="PhysicsConstants.MaxSeamReach"/> past the landblock.</exception>
    public void AddLandblock(
        uint landblockId,
        TerrainSurface terrain,
        IReadOnlyList<CellSurface> cells,
        IReadOnlyList<ObjectSurface> objects)
    {
        _registry.Set(LandblockAssembly.Build(landblockId, terrain, cells, objects));
        _recorder?.LandblockAdded(CellIds.LandblockOf(landblockId));
    }

    /// <summary>Remove all surfaces for an unloaded landblock.</summary>
    /// <remarks>Any low 16 bits are accepted. Removing a landblock that is not registered does nothing, so an unload path may call it unconditionally. One writer thread at a time; resolvers may run meanwhile.</remarks>
    public void RemoveLandblock(uint landblockId)
    {
        int x = CellIds.LandblockX(landblockId), y = CellIds.LandblockY(landblockId);
        _registry.Remove(x, y);
        _recorder?.LandblockRemoved(landblockId);
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
        // The preamble written out, as every query's (PhysicsEngine.Query.cs).
        MoveQuery.Validate(currentPos, currentCellId, delta, stepUpHeight);
        var lands = new Neighbourhood(_registry);
        if (_movers.Any && lands.Meet(_movers, in _frame, currentPos, currentCellId, MathF.Abs(delta.X) + MathF.Abs(delta.Y) + 0.05f, 0))
        {
            return HeldLiteral(ref lands, currentPos, currentCellId, delta, stepUpHeight);
        }

        MovementOptions none = default; // no effects: the spec's engine
        var query = new MoveQuery(ref lands, currentPos, currentCellId, new Vector2(delta.X, delta.Y), stepUpHeight, in none);
        return _point.Step(ref query);
    }

    /// <summary>
    /// <see cref="Resolve(Vector3, uint, Vector3, float)"/> with opt-in effects beyond the spec. With
    /// <c>default(MovementOptions)</c> the answer is bit for bit that of the four-argument call.
    /// </summary>
    /// <param name="currentPos">Where the mover's feet are, world metres.</param>
    /// <param name="currentCellId">The cell the mover is in (<c>0xXXYYCCCC</c>).</param>
    /// <param name="delta">The intended move, world metres; its Z is ignored unless <see cref="MovementOptions.Vertical"/> (with a body) moves the body up and down by it.</param>
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
        // The preamble written out, as the literal call's.
        MoveQuery.Validate(currentPos, currentCellId, delta, stepUpHeight);
        var lands = new Neighbourhood(_registry);
        if (_movers.Any && lands.Meet(_movers, in _frame, currentPos, currentCellId, MoverReach(delta, in options), 0))
        {
            return HeldOptioned(ref lands, new MoveRequest(currentPos, currentCellId, delta, stepUpHeight) { Options = options });
        }

        var query = new MoveQuery(ref lands, currentPos, currentCellId, new Vector2(delta.X, delta.Y), stepUpHeight, in options);
        return Move(ref query, in options, delta.Z);
    }

    private static (int X, int Y) CheckedCentre(uint centerLandblockId)
    {
        CellIds.ValidateLandblockId(centerLandblockId, nameof(centerLandblockId));
        return (CellIds.LandblockX(centerLandblockId), CellIds.LandblockY(centerLandblockId));
    }
}
