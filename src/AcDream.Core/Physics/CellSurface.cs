using System.Numerics;
using AcDream.Core.Dat;

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
public sealed class CellSurface
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
        Walls = CellWalls.Build(cell, physics, _portalShapes, [], nameof(cellStruct));

        (FloorMin, FloorMax) = FloorBounds(_floors);
        _grid = _floors.Length > PhysicsConstants.FloorGridMinTriangles ? new FloorGrid(_floors, FloorMin, FloorMax) : null;
    }

    /// <summary>The engine's copy of <paramref name="cell"/> with the objects standing in it (its <c>StaticObjects</c>), and whether its building has a registered shell.</summary>
    private CellSurface(CellSurface cell, ObjectSurface[] objects, bool shelled)
    {
        _floors = cell._floors;
        _portalShapes = cell._portalShapes;
        HasOpeningAbove = cell.HasOpeningAbove;
        _grid = cell._grid;
        CellId = cell.CellId;
        Origin = cell.Origin;
        Portals = cell.Portals;
        FloorMin = cell.FloorMin;
        FloorMax = cell.FloorMax;
        Walls = cell.Walls;
        Objects = objects;
        IsShelled = shelled;
    }

    /// <summary>Whether the cell has any walkable floor (a stairwell shaft has none).</summary>
    internal bool HasFloor => _floors.Length > 0;

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
    /// (<see cref="ObjectGeometry.RaiseToRest(ReadOnlySpan{ObjectSurface}, float, float, float, float, bool, ref float, out int)"/>).
    /// Without objects, exactly <see cref="TrySampleFloor(float, float, float, out float)"/>.
    /// </summary>
    internal bool TrySampleGround(float x, float y, float feetZ, float stepUp, out float z)
    {
        bool found = TrySampleFloor(x, y, feetZ, out z);
        if (Objects.Length == 0)
        {
            return found;
        }

        return ObjectGeometry.RaiseToRest(Objects, x, y, feetZ, stepUp, found, ref z, out _) || found;
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

    /// <summary>The physics polygons placed in landblock-local space, in id order, each with its winding normal (zero when it has no area).</summary>
    private static List<(ushort Id, Vector3[] Vertices, Vector3 Normal)> PlacePhysicsPolygons(string cell, CellStruct cellStruct, CellTransform transform)
    {
        Dictionary<ushort, Polygon> polygons = cellStruct.PhysicsPolygons
            ?? throw new ArgumentNullException(nameof(cellStruct), $"{cell}: cellStruct.PhysicsPolygons is null.");
        var keys = new List<ushort>(polygons.Keys);
        keys.Sort();
        var placed = new List<(ushort, Vector3[], Vector3)>(keys.Count);
        foreach (ushort key in keys)
        {
            Vector3[] v = transform.Polygon(polygons[key], $"physics polygon {key}");
            placed.Add((key, v, Geometry.NewellNormal(v, v[0])));
        }

        return placed;
    }

    /// <summary>XY bounds of <paramref name="floors"/> (each triangle's, grown by the edge tolerance), landblock-local metres; with no floors, an empty box that contains nothing.</summary>
    internal static (Vector2 Min, Vector2 Max) FloorBounds(FloorTriangle[] floors)
    {
        Vector2 min = new(float.MaxValue), max = new(float.MinValue);
        foreach (FloorTriangle t in floors)
        {
            min = Vector2.Min(min, t.Min);
            max = Vector2.Max(max, t.Max);
        }

        return (min, max);
    }

    /// <summary>The walkable polygons (winding normal Z ≥ <see cref="PhysicsConstants.FloorZ"/>), fan-triangulated.</summary>
    internal static FloorTriangle[] BuildFloors(List<(ushort Id, Vector3[] Vertices, Vector3 Normal)> physics)
    {
        var triangles = new List<FloorTriangle>();
        foreach ((_, Vector3[] v, Vector3 normal) in physics)
        {
            if (normal.Z < PhysicsConstants.FloorZ)
            {
                continue; // a wall, a ceiling, too steep, or no area
            }

            FloorPlane? plane = FloorPlane.OfPolygon(v, normal);
            for (int i = 1; i + 1 < v.Length; i++)
            {
                if (FloorTriangle.TryCreate(v[0], v[i], v[i + 1], plane, out FloorTriangle triangle))
                {
                    triangles.Add(triangle);
                }
            }
        }

        return [.. triangles];
    }

    private static (CellPortalInfo[] Infos, PortalShape[] Shapes) BuildPortals(
        string cell, uint cellId, EnvCell envCell, CellStruct cellStruct, CellTransform transform)
    {
        List<CellPortal> portals = envCell.CellPortals
            ?? throw new ArgumentNullException(nameof(envCell), $"{cell}: envCell.CellPortals is null.");
        Dictionary<ushort, Polygon> polygons = cellStruct.Polygons
            ?? throw new ArgumentNullException(nameof(cellStruct), $"{cell}: cellStruct.Polygons is null.");
        var infos = new CellPortalInfo[portals.Count];
        var shapes = new PortalShape[portals.Count];
        for (int i = 0; i < portals.Count; i++)
        {
            CellPortal portal = portals[i] ?? throw new ArgumentNullException(nameof(envCell), $"{cell}: CellPortals[{i}] is null.");
            if (!polygons.TryGetValue(portal.PolygonId, out Polygon? polygon))
            {
                throw new ArgumentException(
                    $"{cell}: portal {i} (to 0x{portal.OtherCellId:X4}) names polygon {portal.PolygonId}, which cellStruct.Polygons lacks.",
                    nameof(cellStruct));
            }

            Vector3[] v = transform.Polygon(polygon, $"portal {i} polygon {portal.PolygonId}");
            bool cellOnPositiveSide = (portal.Flags & PortalFlags.PortalSide) != 0;
            PortalShape shape = PortalShape.Create(v, cellOnPositiveSide);
            shapes[i] = shape;
            infos[i] = new CellPortalInfo(CellIds.Prefix(cellId) | portal.OtherCellId, shape.Origin, shape.OutNormal);
        }

        return (infos, shapes);
    }

    /// <summary>
    /// <paramref name="q"/> normalised to a unit rotation; false when it is not finite or
    /// shorter than <see cref="PhysicsConstants.MinOrientationLength"/>. Normalised in double: a float
    /// LengthSquared overflows for a quaternion longer than ~1.8e19 (and Quaternion.Normalize then
    /// returns zero, which rotates nothing).
    /// </summary>
    internal static bool TryUnitOrientation(Quaternion q, out Quaternion unit)
    {
        double length = Math.Sqrt(((double)q.X * q.X) + ((double)q.Y * q.Y) + ((double)q.Z * q.Z) + ((double)q.W * q.W));
        if (!float.IsFinite(q.X) || !float.IsFinite(q.Y) || !float.IsFinite(q.Z) || !float.IsFinite(q.W)
            || !(length >= PhysicsConstants.MinOrientationLength))
        {
            unit = default;
            return false;
        }

        unit = new Quaternion((float)(q.X / length), (float)(q.Y / length), (float)(q.Z / length), (float)(q.W / length));
        return true;
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


    /// <summary>Moves a CellStruct's vertices to landblock-local space, validating them once each.</summary>
    private sealed class CellTransform(string cell, CellStruct cellStruct, Vector3 origin, Quaternion orientation)
    {
        private readonly Dictionary<ushort, SWVertex> _vertices = cellStruct.VertexArray?.Vertices
            ?? throw new ArgumentNullException(nameof(cellStruct), $"{cell}: cellStruct.VertexArray.Vertices is null.");

        private readonly Dictionary<short, Vector3> _moved = [];

        public Vector3[] Polygon(Polygon polygon, string what)
        {
            List<short> ids = polygon?.VertexIds
                ?? throw new ArgumentNullException(nameof(cellStruct), $"{cell}: {what} or its VertexIds is null.");
            if (ids.Count < 3)
            {
                throw new ArgumentException($"{cell}: {what} has {ids.Count} vertices; a polygon needs at least 3.", nameof(cellStruct));
            }

            var result = new Vector3[ids.Count];
            for (int i = 0; i < ids.Count; i++)
            {
                result[i] = Vertex(ids[i], what);
            }

            return result;
        }

        private Vector3 Vertex(short id, string what)
        {
            if (_moved.TryGetValue(id, out Vector3 moved))
            {
                return moved;
            }

            if (id < 0 || !_vertices.TryGetValue((ushort)id, out SWVertex? vertex) || vertex is null)
            {
                throw new ArgumentException($"{cell}: {what} names vertex {id}, which the vertex array lacks.", nameof(cellStruct));
            }

            Vector3 local = vertex.Origin;
            if (!Geometry.IsFinite(local))
            {
                throw new ArgumentException($"{cell}: vertex {id} ({what}) is {local}; vertices must be finite.", nameof(cellStruct));
            }

            moved = origin + Vector3.Transform(local, orientation);
            if (!(MathF.Abs(moved.X) <= PhysicsConstants.MaxCellCoordinate && MathF.Abs(moved.Y) <= PhysicsConstants.MaxCellCoordinate
                && MathF.Abs(moved.Z) <= PhysicsConstants.MaxCellCoordinate))
            {
                throw new ArgumentException(
                    $"{cell}: vertex {id} ({what}) is placed at {moved}, farther than {PhysicsConstants.MaxCellCoordinate} m from the landblock.",
                    nameof(cellStruct));
            }

            _moved[id] = moved;
            return moved;
        }
    }
}
