using AcDream.Core.Physics.Surfaces;
namespace AcDream.Core.Physics;

/// <summary>
/// The engine's constants and tolerances, in one place. Lengths are metres.
/// </summary>
public static class PhysicsConstants
{
    /// <summary>Side of a landblock: 192 m (8 outdoor cells of 24 m).</summary>
    public const float LandblockSize = 192f;

    /// <summary>Side of an outdoor cell: 24 m, also the spacing of the terrain's height vertices.</summary>
    public const float CellSize = 24f;

    /// <summary>Outdoor cells per landblock side (8).</summary>
    public const int CellsPerSide = 8;

    /// <summary>Height vertices per landblock side (9).</summary>
    public const int VerticesPerSide = 9;

    /// <summary>Highest landblock X or Y index of the world (the world has 255 × 255 landblocks).</summary>
    public const int MaxLandblockIndex = 254;

    /// <summary>Landblock indices per side of the id space (0x00..0xFF; 0xFF is off the world): the size of the engine's landblock table.</summary>
    public const int WorldSide = 256;

    /// <summary>
    /// How far (metres) an outdoor mover may stand outside the landblock its cell id names and still
    /// be resolved from that landblock: covers the rounding of world positions at seams far from the
    /// origin, where a position can round onto the neighbour's side of the seam.
    /// </summary>
    public const float SeamSlack = 1f;

    /// <summary>
    /// Swept moves: how many times a move refused as a step too high at an object's floor is halved to reach the
    /// step (4: down to a sixteenth of the move, 3 cm of a 0.48 m sub-step), so a mover whose move spans a stair's
    /// tread and the rise beyond it lands on the tread instead of being refused from the floor before it.
    /// </summary>
    public const int MaxClimbHalvings = 4;

    /// <summary>Most sub-steps one swept move takes (see <see cref="MovementOptions.SweepStepLength"/>): 65,536; a longer move gets longer sub-steps.</summary>
    public const int MaxSweepSteps = 1 << 16;

    /// <summary>
    /// A polygon is a walkable floor when the Z of its unit normal is at least this (about 48.4°),
    /// the game's walkable limit. Walls (normal Z = 0) and ceilings (negative) never are.
    /// </summary>
    public const float FloorZ = 0.66417414618662751f;

    /// <summary>The game's landing threshold for airborne movers: unit normal Z of 5°.</summary>
    public const float LandingZ = 0.0871557f;

    /// <summary>
    /// How far outside a polygon's edge a point still counts as on the polygon: 0.2 mm, the game's
    /// general tolerance. It makes a point on an edge or vertex shared by two triangles belong to
    /// both despite rounding, and is far below anything a player can see.
    /// </summary>
    public const float EdgeTolerance = 0.0002f;

    /// <summary>
    /// A portal polygon whose unit normal has |Z| at least this is an opening in a floor or ceiling
    /// (horizontal); below it the portal is a doorway (vertical). 0.5 is 60° from vertical: real
    /// doorways lean a few degrees at most, real floor openings not at all.
    /// </summary>
    public const float HorizontalPortalNormalZ = 0.5f;

    /// <summary>
    /// Largest |coordinate| (metres, landblock-local, on each axis) a cell's vertex may have once
    /// placed: 100 km, twice the width of the world. It keeps every product the floor and portal
    /// tests form finite; no real cell comes near it.
    /// </summary>
    /// <value>100,000 m.</value>
    public const float MaxCellCoordinate = 100_000f;

    /// <summary>
    /// Most cells one move may pass through after leaving the current one (doorway → vestibule →
    /// room, or opening → shaft → cellar). Bounds the search on cyclic portal graphs.
    /// </summary>
    public const int MaxPortalHops = 4;

    /// <summary>
    /// How far (metres) the feet may be from the terrain or floor under them and still stand on it:
    /// 0.2 mm. <see cref="ResolveResult.IsOnGround"/> is true exactly when the returned Z is within
    /// this of the ground under the returned XY; a mover this close above the ground, or below it,
    /// is put on it.
    /// </summary>
    public const float GroundTolerance = 0.0002f;

    /// <summary>
    /// Most cells one move may visit in its portal search, in all (not per path). Real moves visit
    /// three or four; the bound keeps hostile portal graphs (cells with many openings into each other)
    /// from costing more than a few microseconds.
    /// </summary>
    public const int MaxCellVisits = 32;

    /// <summary>
    /// With <see cref="MovementOptions.DoorsOnly"/>: a building's floor from this far (metres) below an
    /// outdoor mover's feet up to <see cref="StoreyAbove"/> above them is a storey the mover would be
    /// standing in, so the floor's outline is the building's outer wall there. A cellar deeper than
    /// this (Holtburg's is 4 m down) is walked over.
    /// </summary>
    public const float StoreyBelow = 3f;

    /// <summary>
    /// With <see cref="MovementOptions.DoorsOnly"/>: see <see cref="StoreyBelow"/>; a floor higher than
    /// this (metres, a player's height) above the feet is overhead, and the mover walks under it
    /// (Holtburg's cottage has an upper storey reaching out over its yard, 3 m up).
    /// </summary>
    public const float StoreyAbove = 2f;

    /// <summary>
    /// Most (grid square, triangle) entries a cell's floor grid keeps per floor triangle. The grid
    /// lists each triangle in every square its bounds overlap; where triangles are large compared with
    /// the squares (thousands of stacked whole-cell floors) the grid is made coarser until the entries
    /// fit, so its memory and build time stay linear in the triangle count. Real cells use about 5.
    /// </summary>
    /// <value>16 entries per triangle (4 bytes each, 12 in a square long enough to be searched by Z).</value>
    public const int MaxFloorGridEntriesPerTriangle = 16;

    /// <summary>
    /// Smallest twice-area (m²) seen from above of a triangle that carries a floor, and smallest
    /// Newell-normal length of a polygon that has a normal: 1e-8 m², a triangle 0.1 mm wide over 0.1 m.
    /// Anything smaller is rounding, not a surface.
    /// </summary>
    internal const double MinFloorDoubleArea = 1e-8;

    /// <summary>Shortest quaternion (length) a cell's orientation may be before it is normalised: 1e-6; shorter is no rotation.</summary>
    internal const double MinOrientationLength = 1e-6;

    /// <summary>A cell with more floor triangles than this gets a floor grid; below it a plain loop is faster.</summary>
    internal const int FloorGridMinTriangles = 16;

    /// <summary>Most squares per side of a floor grid.</summary>
    internal const int FloorGridMaxSide = 64;

    /// <summary>Smallest extent (metres) a floor grid spans on each axis, so a sliver floor still gets squares of a sensible size.</summary>
    internal const float FloorGridMinExtent = 0.25f;

    /// <summary>
    /// A floor-grid square listing at most this many triangles is searched by a plain loop, as a small
    /// cell is; longer runs are kept in order of lowest Z and searched outwards from the reference Z.
    /// Real cells list at most about 11 per square.
    /// </summary>
    internal const int FloorGridLinearScanMax = 16;

    /// <summary>
    /// Body: how far, metres, a physics polygon's vertices may lie from a portal's plane for the
    /// polygon to count as the doorway's cover (not a wall). Real doorways' covers lie in the plane.
    /// </summary>
    public const float DoorwayCoverTolerance = 0.01f;

    /// <summary>
    /// Body: a body within this distance, metres, of a wall (beyond its radius) counts as touching it:
    /// a move into it is stopped at once and slides. Keeps a body resting against a wall from being
    /// pushed through it by rounding.
    /// </summary>
    public const float ContactTolerance = 0.0001f;

    /// <summary>Body: the most walls one call slides along (the contacts of collide-and-slide).</summary>
    public const int MaxBodyContacts = 4;

    /// <summary>
    /// Body: how many cells and objects one call lists as the walls around it (on the stack, 4 bytes each).
    /// Only a speed-up: where more stand near, every sweep of the call asks the landblock's grids again over
    /// its own box, so no wall is ever left out. Real moves list a handful (the cottage is 16 cells).
    /// </summary>
    internal const int BodySources = 64;

    /// <summary>Body: the smallest gap, metres, the body keeps from walls beyond its radius (the world frame's rounding is added to it).</summary>
    public const float BodySkin = 0.00001f;

    /// <summary>
    /// The most vertices a wall polygon may have (the body cuts each on the stack). Real physics
    /// polygons have 3 to 8; a cell with a longer non-floor polygon is rejected when built.
    /// </summary>
    public const int MaxWallPolygonVertices = 64;

    /// <summary>
    /// How far a mover's walls may reach from its origin, seen from above, metres (<see cref="MoverShape.Reach"/>): the
    /// movers near a move are found by their origins, within this.
    /// </summary>
    public const float MaxMoverReach = 24f;

    /// <summary>
    /// How near a mover's disc comes to another mover's walls to touch it, metres (<c>Resolve</c> with a touch
    /// buffer): a body held at a wall stops within its skin and the contact tolerance of it.
    /// </summary>
    public const float TouchReach = 0.001f;

    /// <summary>The size of the squares the registered movers are filed in by their origins, metres.</summary>
    internal const float MoverGridCell = 2f;

    /// <summary>
    /// Most outdoor objects one landblock may register (its <c>LandBlockInfo</c>'s objects and
    /// buildings). A bound on the memory and build time of one registration, far above real data.
    /// </summary>
    public const int MaxOutdoorObjects = 7_000;

    /// <summary>
    /// How far, metres, anything an outdoor mover meets may reach past the edge of the landblock that
    /// registers it (an outdoor object, with its floors; the walls of a building's cells): 24 m, one outdoor
    /// cell. A mover looks at a neighbouring landblock's objects and walls only when its move comes this
    /// close to their seam, so one far from every seam reads its own landblock alone. Registering more is an
    /// <see cref="ArgumentException"/> naming the object or cell. Holtburg's cellar reaches 1 m past its seam.
    /// </summary>
    /// <value>24 m.</value>
    public const float MaxSeamReach = 24f;

    /// <summary>
    /// Margin, metres, by which a move's box is grown before the objects' fine grid is asked about it, so
    /// rounding the move into a landblock's frame never leaves a square out: 1 cm.
    /// </summary>
    internal const float NearMargin = 0.01f;

    /// <summary>The side of a square of a cell's open floor (<see cref="OpenFloor"/>), metres.</summary>
    internal const float OpenFloorSquare = 1f;

    /// <summary>
    /// Body in the air (<see cref="MovementOptions.Vertical"/>): the most its horizontal move climbs, metres (0.04 m, the
    /// game's step up while not on walkable ground), whatever the caller's step; higher edges are walls to it.
    /// </summary>
    public const float AirStepUp = 0.04f;

    /// <summary>
    /// Footing (<see cref="MovementOptions.Footing"/>): how far past a floor's edge, as a fraction of the body's radius,
    /// its centre may be and the floor still hold it: 0.5, the game's (a 0.48 m body centred 0.239 m past an edge is
    /// held, 0.241 m is not).
    /// </summary>
    public const float SupportReach = 0.5f;

    /// <summary>
    /// The largest radius a cast's sphere may have (<see cref="CastOptions.Radius"/>): 24 m, one outdoor cell. The spheres
    /// cast are a camera's (0.3 m), a pointer's ray (0) or a body's (a metre or so); a sphere of this radius reaches into
    /// at most the 4 × 4 terrain cells around each cell its centre crosses and, grown by it, a stretch of the path stays
    /// within the landblocks next to the one it is in, so a cast's cost grows with the cells its path crosses.
    /// </summary>
    public const float MaxCastRadius = CellSize;

    /// <summary>
    /// Cast (<see cref="PhysicsEngine.Cast"/>): how far outside a polygon's edges, metres, its face still stops a ray or
    /// sphere: 1 µm. Two polygons sharing an edge then leave no gap for a ray whose touch point rounds off both (double
    /// rounding of the inside test is about 1e-13 m in a landblock), and a point this far off an edge is well within
    /// the 0.1 mm to which a contact is promised.
    /// </summary>
    internal const double CastEdgeTolerance = 1e-6;

    /// <summary>
    /// Cast: margin, metres, by which the box of a stretch of the path (grown by the radius) is grown again before the
    /// grids and bounds are asked about it, so rounding it to floats never leaves a shape out: 1 mm.
    /// </summary>
    internal const double CastBoxMargin = 1e-3;
}
