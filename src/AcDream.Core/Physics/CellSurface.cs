using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics.Surfaces;

namespace AcDream.Core.Physics;

/// <summary>
/// Indoor floor of one EnvCell, in landblock-local metres (the frame <c>EnvCell.Position</c> is
/// expressed in; a cell's geometry may reach past 0..192, as Holtburg's cellar does).
/// </summary>
/// <remarks>
/// At construction the cell's physics polygons are moved from cell-local to landblock-local space
/// (<c>Origin + Vector3.Transform(v, Orientation)</c>, the orientation normalised), the floors are
/// kept (winding normal Z ≥ <see cref="PhysicsConstants.FloorZ"/>; walls and ceilings never are) and
/// fan-triangulated (triangles with no area, facing down, or thinner than
/// <see cref="PhysicsConstants.EdgeTolerance"/> dropped), and the portals are prepared for crossing
/// tests. A floor's Z is its polygon's plane (the plane through the vertices' mean with the winding
/// normal) when every vertex lies within <see cref="PhysicsConstants.EdgeTolerance"/> of it, else each
/// triangle's own plane; always clamped to the triangle's Z range. Queries are arithmetic only and
/// allocate nothing. Instances are immutable and safe to share between threads.
/// </remarks>
public sealed partial class CellSurface
{
    private readonly FloorTriangle[] _floors;
    private readonly PortalShape[] _portalShapes;

    /// <summary>Uniform grid over the floor triangles; null for small floors, where brute force is faster.</summary>
    private readonly FloorGrid? _grid;

    /// <summary>The EnvCell's dat id (e.g., 0xA9B40100).</summary>
    public uint CellId { get; }

    /// <summary>The cell's origin (from EnvCell.Position.Origin), landblock-local metres.</summary>
    /// <remarks>As stored in the dat; <see cref="PhysicsEngine.ToWorld"/> adds the landblock's offset.</remarks>
    public Vector3 Origin { get; }

    /// <summary>Portal connections to adjacent cells.</summary>
    /// <remarks>In the order of <c>EnvCell.CellPortals</c>; geometry in landblock-local metres.</remarks>
    public IReadOnlyList<CellPortalInfo> Portals { get; }

    /// <summary>
    /// Prepares the floors and portals of one EnvCell.
    /// </summary>
    /// <param name="cellId">Full cell id, <c>0xXXYYCCCC</c> with <c>CCCC</c> in 0x0100..0xFFFD. If <c>envCell.Id</c> is set (non-zero) it must be the same.</param>
    /// <param name="envCell">The cell: its <c>Position</c> places the geometry, its <c>CellPortals</c> give the portals.</param>
    /// <param name="cellStruct">The cell's shape: <c>PhysicsPolygons</c> give the floors, <c>Polygons</c> the portal polygons.</param>
    /// <exception cref="ArgumentNullException">An argument, or a list inside them, is null.</exception>
    /// <exception cref="ArgumentException">
    /// The id is not an indoor cell id or disagrees with <c>envCell.Id</c>; the position is not finite
    /// or its orientation is zero (length below 1e-6; any longer quaternion is normalised, in double);
    /// a polygon has fewer than three vertices, names an unknown vertex, or has a non-finite vertex, or
    /// one that, placed, lies farther than <see cref="PhysicsConstants.MaxCellCoordinate"/> from the
    /// landblock's origin on any axis; a portal names a polygon that <c>Polygons</c> lacks. The message
    /// names the cell, the polygon or portal, and what is wrong.
    /// </exception>
    public CellSurface(uint cellId, EnvCell envCell, CellStruct cellStruct)
    {
        ArgumentNullException.ThrowIfNull(envCell);
        ArgumentNullException.ThrowIfNull(cellStruct);
        string cell = $"cell 0x{cellId:X8}";
        if (!CellIds.IsIndoor(cellId))
        {
            throw new ArgumentException($"{cell}: not an indoor cell id; the low 16 bits must be 0x0100..0xFFFD.", nameof(cellId));
        }

        if (envCell.Id != 0 && envCell.Id != cellId)
        {
            throw new ArgumentException($"{cell}: envCell.Id is 0x{envCell.Id:X8}, a different cell.", nameof(envCell));
        }

        Frame position = envCell.Position ?? throw new ArgumentNullException(nameof(envCell), $"{cell}: envCell.Position is null.");
        Vector3 origin = position.Origin;
        Quaternion orientation = position.Orientation;
        if (!Geometry.IsFinite(origin))
        {
            throw new ArgumentException($"{cell}: Position.Origin {origin} is not finite.", nameof(envCell));
        }

        if (!TryUnitOrientation(orientation, out Quaternion unit))
        {
            throw new ArgumentException($"{cell}: Position.Orientation {orientation} is not a rotation (non-finite, or shorter than 1e-6).", nameof(envCell));
        }

        CellId = cellId;
        Origin = origin;
        var transform = new CellTransform(cell, cellStruct, origin, unit);

        List<(ushort Id, Vector3[] Vertices, Vector3 Normal)> physics = PlacePhysicsPolygons(cell, cellStruct, transform);
        _floors = BuildFloors(physics);
        (Portals, _portalShapes) = BuildPortals(cell, cellId, envCell, cellStruct, transform);
        HasOpeningAbove = Array.Exists(_portalShapes, static p => p.Kind == PortalKind.Horizontal && p.OutNormal.Z > 0f);
        FloorLevel = _floors.Length > 0 && Array.TrueForAll(_floors, f => f.ZMin == _floors[0].ZMin && f.ZMax == _floors[0].ZMin) ? _floors[0].ZMin : float.NaN;
        (FloorZMin, FloorZMax) = _floors.Length == 0 ? (float.MaxValue, float.MinValue) : (_floors.Min(f => f.ZMin), _floors.Max(f => f.ZMax));
        Walls = CellWalls.Build(cell, physics, _portalShapes, [], nameof(cellStruct));

        (FloorMin, FloorMax) = FloorBounds(_floors);
        _grid = _floors.Length > PhysicsConstants.FloorGridMinTriangles ? new FloorGrid(_floors, FloorMin, FloorMax) : null;
        PortalExtents = Array.ConvertAll(_portalShapes, static p => WallExtent.Pack(p.BoundsMin, p.BoundsMax));
        OpenFloor = OpenFloor.Build(this);
    }

    /// <summary>The engine's copy of <paramref name="cell"/> with the objects standing in it (its <c>StaticObjects</c>), and whether its building has a registered shell.</summary>
    private CellSurface(CellSurface cell, ObjectSurface[] objects, bool shelled)
    {
        _floors = cell._floors;
        _portalShapes = cell._portalShapes;
        HasOpeningAbove = cell.HasOpeningAbove;
        FloorLevel = cell.FloorLevel;
        (FloorZMin, FloorZMax) = (cell.FloorZMin, cell.FloorZMax);
        _grid = cell._grid;
        CellId = cell.CellId;
        Origin = cell.Origin;
        Portals = cell.Portals;
        FloorMin = cell.FloorMin;
        FloorMax = cell.FloorMax;
        Walls = cell.Walls;
        Objects = objects;
        IsShelled = shelled;
        PortalExtents = cell.PortalExtents;
        OpenFloor = objects.Length == 0 ? cell.OpenFloor : OpenFloor.Build(this); // the objects' walls are in it
    }

    /// <summary>Its portals' bounds seen from above, packed (<see cref="WallExtent.Pack"/>), in its portals' order.</summary>
    internal System.Runtime.Intrinsics.Vector128<float>[] PortalExtents { get; }

    /// <summary>Where its floor is open to a body (<see cref="OpenFloor"/>), with the objects standing in it; null without a floor.</summary>
    internal OpenFloor? OpenFloor { get; }

    /// <summary>Whether the cell has any walkable floor (a stairwell shaft has none).</summary>
    internal bool HasFloor => _floors.Length > 0;

    /// <summary>The walkable triangles, landblock-local, as the floor queries sample them.</summary>
    internal ReadOnlySpan<FloorTriangle> Floors => _floors;

    /// <summary>The objects standing in this cell (the engine's copy; empty on a caller's).</summary>
    internal ObjectSurface[] Objects { get; } = [];

    /// <summary>Whether the cell belongs to a building whose shell is registered: entering it from outdoors is decided by the shell's walls.</summary>
    internal bool IsShelled { get; }

    /// <summary>This cell with <paramref name="objects"/> standing in it and its shell flag: a new instance, this one unchanged.</summary>
    internal CellSurface WithObjects(ObjectSurface[] objects, bool shelled) => new(this, objects, shelled);

    /// <summary>
    /// The ground a mover with its feet at <paramref name="feetZ"/> and step <paramref name="stepUp"/>
    /// stands on at (x, y): the cell's floor nearest the feet, or the floor of an object standing in the
    /// cell that is higher than that and no more than the step above the feet (a thing on the floor is
    /// climbed when it is low enough), and so on from there to rest
    /// (<see cref="ObjectFloors.RaiseToRest"/>).
    /// Without objects, exactly <see cref="TrySampleFloor(float, float, float, out float)"/>.
    /// </summary>
    internal bool TrySampleGround(float x, float y, float feetZ, float stepUp, out float z)
    {
        bool found = TrySampleFloor(x, y, feetZ, out z);
        if (Objects.Length == 0)
        {
            return found;
        }

        var rest = new FloorRest(z, found);
        bool raised = ObjectFloors.RaiseToRest(Objects, new Vector2(x, y), feetZ, stepUp, ref rest);
        z = rest.Z;
        return raised || found;
    }

    /// <summary>Landblock-local XY bounds of the floor, grown by the edge tolerance; empty when there is no floor.</summary>
    internal Vector2 FloorMin { get; }

    internal Vector2 FloorMax { get; }

    /// <summary>The cell's walls for the body effect (every physics polygon that is not a floor or a doorway's cover).</summary>
    internal CellWalls Walls { get; }

    /// <summary>Bounds (landblock-local metres) of its walls and its objects' walls; empty (min &gt; max) when it has none.</summary>
    internal WallBounds WallBounds()
    {
        var bounds = new WallBounds(Walls.Min, Walls.Max, Walls.ZMin, Walls.ZMax);
        foreach (ObjectSurface o in Objects)
        {
            bounds = bounds.With(new WallBounds(o.Walls.Min, o.Walls.Max, o.Walls.ZMin, o.Walls.ZMax));
        }

        return bounds;
    }

    /// <summary>Whether one of the cell's portals is an opening in its ceiling (a horizontal portal leading up).</summary>
    internal bool HasOpeningAbove { get; }

    /// <summary>The Z of the cell's floors when they are all level at one height (landblock-local metres); NaN when they are not, or there are none.</summary>
    internal float FloorLevel { get; }

    /// <summary>The lowest and highest Z of the cell's floors, metres (empty, min &gt; max, when there are none).</summary>
    internal float FloorZMin { get; }

    internal float FloorZMax { get; }

    /// <summary>Prepared portal geometry, aligned with <see cref="Portals"/>.</summary>
    internal ReadOnlySpan<PortalShape> PortalShapes => _portalShapes;

    /// <summary>
    /// Project (worldX, worldY), landblock-local metres despite the names, onto this cell's floor polygons and
    /// return the Z height at that point. Returns null if the XY
    /// doesn't fall within any floor polygon (the entity isn't over
    /// this cell's floor).
    ///
    /// <para>
    /// Uses PhysicsPolygons (not rendering Polygons): the walkable ones (winding normal Z at least
    /// <see cref="PhysicsConstants.FloorZ"/>), fan-triangulated once at construction. A query looks
    /// only at the triangles a uniform grid lists near the point (all of them for small floors) and
    /// takes the Z of the polygon's plane there (see the class remarks).
    /// </para>
    /// </summary>
    /// <remarks>
    /// Coordinates and the result are landblock-local metres. Where floors are stacked, the topmost
    /// one under the point wins, whatever the polygon order. A point on an edge or vertex, or within
    /// <see cref="PhysicsConstants.EdgeTolerance"/> of one, is on the floor. The Z is the plane's (see
    /// the class remarks), not a blend of one triangle's vertices, so it is the same on both sides of a
    /// polygon's inner edges and no thin triangle can skew it.
    /// </remarks>
    /// <exception cref="ArgumentException">A coordinate is NaN or infinite.</exception>
    public float? SampleFloorZ(float worldX, float worldY)
    {
        ThrowIfNotFinite(worldX, worldY, 0f);
        return TrySampleFloor(worldX, worldY, float.PositiveInfinity, out float z) ? z : null;
    }

    /// <summary>
    /// Like <see cref="SampleFloorZ(float, float)"/>, but where floors are stacked (a cellar under a
    /// ground floor, an upper storey) returns the floor whose Z is nearest to
    /// <paramref name="referenceZ"/>; on an exact tie, the higher one.
    /// </summary>
    /// <param name="worldX">Landblock-local X, metres.</param>
    /// <param name="worldY">Landblock-local Y, metres.</param>
    /// <param name="referenceZ">Landblock-local Z to compare with, metres (typically the mover's feet).</param>
    /// <returns>The floor Z in metres, or null when no floor lies under (x, y).</returns>
    /// <exception cref="ArgumentException">An argument is NaN or infinite.</exception>
    public float? SampleFloorZ(float worldX, float worldY, float referenceZ)
    {
        ThrowIfNotFinite(worldX, worldY, referenceZ);
        return TrySampleFloor(worldX, worldY, referenceZ, out float z) ? z : null;
    }

    /// <summary>
    /// The engine's query: the floor under (x, y) nearest to <paramref name="referenceZ"/>
    /// (positive infinity: the topmost). Arguments must be finite or +∞ for the reference.
    /// </summary>
    internal bool TrySampleFloor(float x, float y, float referenceZ, out float z)
    {
        z = 0f;
        if (x < FloorMin.X || y < FloorMin.Y || x > FloorMax.X || y > FloorMax.Y)
        {
            return false;
        }

        if (_grid is not null)
        {
            return _grid.TrySample(x, y, referenceZ, out z);
        }

        bool found = false;
        float best = float.PositiveInfinity;
        foreach (ref readonly FloorTriangle triangle in _floors.AsSpan())
        {
            FloorGrid.Keep(triangle, x, y, referenceZ, ref found, ref best, ref z);
        }

        return found;
    }

    /// <summary>
    /// <see cref="TrySampleFloor(float, float, float, out float)"/> with the unit normal (pointing up)
    /// of the floor found. For the host's queries, not the per-move path: it scans the floor once more.
    /// </summary>
    internal bool TrySampleFloor(float x, float y, float referenceZ, out float z, out Vector3 normal)
    {
        normal = default;
        if (!TrySampleFloor(x, y, referenceZ, out z))
        {
            return false;
        }

        TryFloorNormal(_floors, x, y, z, out normal);
        return true;
    }

    /// <summary>
    /// The unit normal (pointing up) of the first of <paramref name="floors"/> that lies under (x, y)
    /// at exactly <paramref name="z"/> (landblock-local metres): the floor a sample there found.
    /// False, with a zero normal, when none does.
    /// </summary>
    internal static bool TryFloorNormal(FloorTriangle[] floors, float x, float y, float z, out Vector3 normal)
    {
        foreach (FloorTriangle triangle in floors)
        {
            if (triangle.TrySample(x, y, out float at) && at == z)
            {
                normal = triangle.Normal;
                return true;
            }
        }

        normal = default;
        return false;
    }

    /// <summary>
    /// The walkable triangles of this cell's floor, exactly as the engine samples them (landblock-local
    /// metres): what a map should draw so that it cannot disagree with the physics. A new array each call.
    /// </summary>
    public FloorTriangleInfo[] GetFloorTriangles() => FloorInfos(_floors);

    /// <summary>The triangles as a caller sees them: a new array.</summary>
    internal static FloorTriangleInfo[] FloorInfos(FloorTriangle[] floors)
    {
        var result = new FloorTriangleInfo[floors.Length];
        for (int i = 0; i < result.Length; i++)
        {
            ref readonly FloorTriangle t = ref floors[i];
            result[i] = new FloorTriangleInfo(
                new Vector3(t.A, t.ZAt(t.A)), new Vector3(t.B, t.ZAt(t.B)), new Vector3(t.C, t.ZAt(t.C)));
        }

        return result;
    }

    private static void ThrowIfNotFinite(float x, float y, float z)
    {
        if (!float.IsFinite(x) || !float.IsFinite(y) || !float.IsFinite(z))
        {
            throw new ArgumentException(
                $"floor query ({x}, {y}, reference {z}) must be finite.",
                !float.IsFinite(x) ? "worldX" : !float.IsFinite(y) ? "worldY" : "referenceZ");
        }
    }
}
