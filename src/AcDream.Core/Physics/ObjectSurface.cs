using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.Point;

namespace AcDream.Core.Physics;

/// <summary>
/// The collision geometry of one placed object (a GfxObj, every part of a Setup, or a building's
/// shell), in landblock-local metres: its floors (walkable physics polygons: stair treads, ramps,
/// plinths, roofs), its walls (every other physics polygon) and its cylinders (a Setup's
/// <see cref="CylSphere"/>s, round walls of their height). Built once; immutable and safe to share
/// between threads. Registered with <see cref="PhysicsEngine.AddLandblock(uint, TerrainSurface, IReadOnlyList{CellSurface}, IReadOnlyList{ObjectSurface})"/>.
/// </summary>
/// <remarks>
/// <para>
/// A vertex is placed as the game places it: scaled by its part's default scale, then by the part's
/// frame of the Setup's <see cref="Placement.Default"/> pose, then by the object's frame
/// (<c>Origin + Vector3.Transform(v, Orientation)</c>, the orientation normalised). A polygon is a floor
/// when its winding normal's Z is at least <see cref="PhysicsConstants.FloorZ"/>; polygons with no area
/// are dropped.
/// </para>
/// <para>
/// <see cref="CellId"/> says where the object stands: 0 (or any outdoor cell id) outdoors, where it
/// meets outdoor movers; an indoor cell id for an <see cref="EnvCell.StaticObjects"/> entry, where it
/// meets movers in that cell. A building's shell (<see cref="IsBuilding"/>) stands outdoors and names
/// the door cells its portals lead to: with it registered, entering those cells from outdoors is decided
/// by its walls and openings, not by the doors-only rule.
/// </para>
/// </remarks>
public sealed partial class ObjectSurface
{
    private readonly FloorTriangle[] _floors;
    private readonly uint[] _doorCells;

    private readonly Placed _placed;

    private ObjectSurface(uint objectId, uint cellId, Placed placed, bool isBuilding, uint[] doorCells)
    {
        _placed = placed;
        ObjectId = objectId;
        CellId = CellIds.IsIndoor(cellId) ? cellId : 0;
        IsBuilding = isBuilding;
        _doorCells = doorCells;
        string what = Name(objectId);
        _floors = CellSurface.BuildFloors(placed.Polygons);
        Walls = CellWalls.Build(what, placed.Polygons, [], placed.Cylinders, "gfxObj");
        (FloorMin, FloorMax) = CellSurface.FloorBounds(_floors);
        (BoundsMin, BoundsMax) = placed.Bounds();
        Exact = ExactPolygons.Build(placed.Polygons, placed.Exact, Walls, _floors);
    }

    /// <summary>The GfxObj or Setup id of the object (for a building, its <see cref="BuildingInfo.ModelId"/>).</summary>
    public uint ObjectId { get; }

    /// <summary>The indoor cell the object belongs to, or 0 when it stands outdoors.</summary>
    public uint CellId { get; }

    /// <summary>Whether the object is a building's outer shell.</summary>
    public bool IsBuilding { get; }

    /// <summary>A building's door cells (full ids), from its <see cref="BuildingInfo.Portals"/>; empty for other objects.</summary>
    public IReadOnlyList<uint> DoorCellIds => _doorCells;

    /// <summary>Lowest corner of the box around all its geometry, landblock-local metres.</summary>
    public Vector3 BoundsMin { get; }

    /// <summary>Highest corner of the box around all its geometry, landblock-local metres.</summary>
    public Vector3 BoundsMax { get; }

    /// <summary>The walls and cylinders (landblock-local) the movers meet.</summary>
    internal CellWalls Walls { get; }

    /// <summary>The walkable triangles, landblock-local, as the floor queries sample them.</summary>
    internal ReadOnlySpan<FloorTriangle> Floors => _floors;

    /// <summary>Its walls' and floors' vertices placed in double precision, as a cast meets them.</summary>
    internal ExactPolygons Exact { get; }

    /// <summary>XY bounds of the floors, grown by the edge tolerance; empty when there are none.</summary>
    internal Vector2 FloorMin { get; }

    internal Vector2 FloorMax { get; }

    /// <summary>A GfxObj placed by <paramref name="frame"/> (object-local → landblock-local).</summary>
    /// <param name="gfxObj">The object; its <c>PhysicsPolygons</c> and <c>VertexArray</c> are read.</param>
    /// <param name="frame">Its placement, object-local → landblock-local metres (a <see cref="Stab.Frame"/>); the orientation is normalised.</param>
    /// <param name="cellId">0 (or any outdoor cell id) outdoors, or the indoor cell it stands in.</param>
    /// <exception cref="ArgumentNullException">An argument, or a list inside it, is null.</exception>
    /// <exception cref="ArgumentException">The id is not a GfxObj id (0x01xxxxxx); the frame is not finite or its orientation is shorter than 1e-6; a polygon has fewer than three vertices, names an unknown vertex, has a non-finite vertex or one placed farther than <see cref="PhysicsConstants.MaxCellCoordinate"/> from the landblock; the message names the object and what is wrong.</exception>
    public ObjectSurface(GfxObj gfxObj, Frame frame, uint cellId)
        : this(CheckedId(gfxObj?.Id, 0x01, nameof(gfxObj)), cellId, Place(gfxObj!, frame), isBuilding: false, [])
    {
    }

    /// <summary>A Setup placed by <paramref name="frame"/>: every part (found in <paramref name="gfxObjs"/>) and every cylinder.</summary>
    /// <param name="setup">The setup; its parts, default scales, default pose and cylinders are read.</param>
    /// <param name="gfxObjs">The GfxObjs by id; every part must be there.</param>
    /// <param name="frame">Its placement, setup-local → landblock-local metres (a <see cref="Stab.Frame"/>); the orientation is normalised.</param>
    /// <param name="cellId">0 (or any outdoor cell id) outdoors, or the indoor cell it stands in.</param>
    /// <exception cref="ArgumentNullException">An argument, or a list inside it, is null.</exception>
    /// <exception cref="ArgumentException">The id is not a Setup id (0x02xxxxxx); as for a GfxObj (for the frame and for each part's polygons); also a part missing from <paramref name="gfxObjs"/>, a pose or scale list of the wrong length, a non-finite part scale or a part frame of the default pose that is not a placement, or a cylinder with a non-finite origin or a non-finite or negative size.</exception>
    public ObjectSurface(Setup setup, IReadOnlyDictionary<uint, GfxObj> gfxObjs, Frame frame, uint cellId)
        : this(CheckedId(setup?.Id, 0x02, nameof(setup)), cellId, Place(setup!, gfxObjs, frame), isBuilding: false, [])
    {
    }

    /// <summary>A building's shell (its <see cref="BuildingInfo.ModelId"/>, a GfxObj or Setup) at its frame, with its door cells.</summary>
    /// <param name="landblockId">The landblock the building stands in (its door cells carry this prefix).</param>
    /// <param name="building">The building.</param>
    /// <param name="gfxObjs">The GfxObjs by id.</param>
    /// <param name="setups">The Setups by id.</param>
    /// <exception cref="ArgumentNullException">An argument, or a list inside it, is null.</exception>
    /// <exception cref="ArgumentException">The model is missing or bad (as for the constructors), or a portal names a door cell outside 0x0100..0xFFFD.</exception>
    public static ObjectSurface Building(uint landblockId, BuildingInfo building, IReadOnlyDictionary<uint, GfxObj> gfxObjs, IReadOnlyDictionary<uint, Setup> setups)
    {
        ArgumentNullException.ThrowIfNull(building);
        ArgumentNullException.ThrowIfNull(gfxObjs);
        ArgumentNullException.ThrowIfNull(setups);
        List<BuildingPortal> portals = building.Portals ?? throw new ArgumentNullException(nameof(building), $"{Name(building.ModelId)}: building.Portals is null.");
        var doors = new uint[portals.Count];
        for (int i = 0; i < doors.Length; i++)
        {
            BuildingPortal portal = portals[i] ?? throw new ArgumentNullException(nameof(building), $"{Name(building.ModelId)}: Portals[{i}] is null.");
            uint door = CellIds.Prefix(landblockId) | portal.OtherCellId;
            if (!CellIds.IsIndoor(door))
            {
                throw new ArgumentException($"{Name(building.ModelId)}: portal {i} leads to 0x{portal.OtherCellId:X4}, not an indoor cell.", nameof(building));
            }

            doors[i] = door;
        }

        return new ObjectSurface(building.ModelId, 0, PlaceModel(building.ModelId, building.Frame, gfxObjs, setups, nameof(building)), isBuilding: true, doors);
    }

    /// <summary>
    /// Every object of a landblock, mapped 1:1 from the dat: each of <paramref name="info"/>'s
    /// <c>Objects</c> and <c>Buildings</c> (outdoors) and each cell's <c>StaticObjects</c> (in that cell).
    /// </summary>
    /// <param name="landblockId">The landblock.</param>
    /// <param name="info">Its object list (<c>0xXXYYFFFE</c>), or null when it has none.</param>
    /// <param name="cells">Its indoor cells (their <c>Id</c> must be set).</param>
    /// <param name="gfxObjs">The GfxObjs by id.</param>
    /// <param name="setups">The Setups by id.</param>
    /// <exception cref="ArgumentNullException"><paramref name="cells"/>, <paramref name="gfxObjs"/> or <paramref name="setups"/> is null, or a stab, a building, a frame or a list inside a model or building is null (null cells and null object lists are skipped).</exception>
    /// <exception cref="ArgumentException">An object's id is neither a GfxObj (0x01xxxxxx) nor a Setup (0x02xxxxxx) id or is not among those given, its model is bad (see the constructors), or a building's portal names a door cell outside 0x0100..0xFFFD; the message names the object.</exception>
    public static List<ObjectSurface> FromLandblock(
        uint landblockId, LandBlockInfo? info, IReadOnlyList<EnvCell> cells, IReadOnlyDictionary<uint, GfxObj> gfxObjs, IReadOnlyDictionary<uint, Setup> setups)
    {
        ArgumentNullException.ThrowIfNull(cells);
        ArgumentNullException.ThrowIfNull(gfxObjs);
        ArgumentNullException.ThrowIfNull(setups);
        var result = new List<ObjectSurface>();
        if (info is not null)
        {
            foreach (Stab stab in info.Objects ?? [])
            {
                result.Add(FromStab(stab, 0, gfxObjs, setups));
            }

            foreach (BuildingInfo building in info.Buildings ?? [])
            {
                result.Add(Building(landblockId, building, gfxObjs, setups));
            }
        }

        foreach (EnvCell cell in cells)
        {
            foreach (Stab stab in cell?.StaticObjects ?? [])
            {
                result.Add(FromStab(stab, cell!.Id, gfxObjs, setups));
            }
        }

        return result;
    }

    /// <summary>The walkable triangles of the object's floors, exactly as the engine samples them (landblock-local metres). A new array each call.</summary>
    public FloorTriangleInfo[] GetFloorTriangles() => CellSurface.FloorInfos(_floors);

    /// <summary>Its walls seen from above (landblock-local metres): each wall polygon's outline, and each cylinder as its centre with <c>Radius</c> > 0. A new array each call.</summary>
    public ObjectWallInfo[] GetWalls()
    {
        var result = new ObjectWallInfo[Walls.Polygons.Length];
        for (int i = 0; i < result.Length; i++)
        {
            WallPolygon w = Walls.Polygons[i];
            Vector3[] outline = w.Radius > 0f
                ? [new Vector3(w.A, w.ZMin), new Vector3(w.A, w.ZMax)]
                : Walls.Vertices.AsSpan(w.First, w.Count).ToArray();
            result[i] = new ObjectWallInfo(outline, w.Radius);
        }

        return result;
    }

    /// <summary>
    /// This object seen from a neighbouring landblock: its geometry moved by <paramref name="offset"/>
    /// (this landblock's frame → the neighbour's), without door cells (they belong to this landblock).
    /// </summary>
    internal ObjectSurface Shifted(Vector2 offset) => new(ObjectId, 0, _placed.Shifted(new Vector3(offset, 0f)), IsBuilding, []);

    /// <summary>
    /// The floor of this object under (x, y) (landblock-local) that is highest without being more
    /// than <paramref name="ceilingZ"/>: what a mover whose feet plus step reach that high stands on.
    /// </summary>
    internal bool TryFloorBelow(float x, float y, float ceilingZ, out float z)
    {
        z = float.NegativeInfinity;
        if (x < FloorMin.X || y < FloorMin.Y || x > FloorMax.X || y > FloorMax.Y)
        {
            return false;
        }

        bool found = false;
        foreach (ref readonly FloorTriangle triangle in _floors.AsSpan())
        {
            if (triangle.ZMin <= ceilingZ && triangle.TrySample(x, y, out float candidate) && candidate <= ceilingZ && candidate > z)
            {
                (z, found) = (candidate, true);
            }
        }

        return found;
    }

    /// <summary>
    /// Whether a floor of this object rises through the height of <paramref name="line"/> (a point mover's feet plus
    /// its step) on its move (landblock-local) before fraction <paramref name="t"/>: the move comes from where the floor's plane is at or below that line to
    /// where it is above it, crossing it within the floor. The mover would pass under a floor (a ramp rising ahead
    /// of it) that its step line runs into, so it is stopped there as by a rise too high: <paramref name="t"/> is
    /// where, <paramref name="normal"/> the horizontal unit normal facing the mover (down the slope).
    /// </summary>
    internal bool RisesThrough(in StepLine line, ref float t, ref Vector3 normal)
    {
        (Vector2 p0, Vector2 p1, Vector2 lo, Vector2 hi, float h) = (line.P0, line.P1, line.Lo, line.Hi, line.H);
        if (FloorMin.X > hi.X || FloorMax.X < lo.X || FloorMin.Y > hi.Y || FloorMax.Y < lo.Y)
        {
            return false;
        }

        bool rises = false;
        foreach (ref readonly FloorTriangle triangle in _floors.AsSpan())
        {
            if (!(triangle.ZMin <= h && triangle.ZMax > h) || triangle.Min.X > hi.X || triangle.Max.X < lo.X || triangle.Min.Y > hi.Y || triangle.Max.Y < lo.Y)
            {
                continue; // wholly below or above the line, or off the move
            }

            float z0 = triangle.PlaneAt(p0), z1 = triangle.PlaneAt(p1);
            if (!(z0 <= h && z1 > h))
            {
                continue;
            }

            float at = (h - z0) / (z1 - z0);
            Vector2 c = p0 + ((p1 - p0) * at);
            if (at < t && triangle.TrySample(c.X, c.Y, out _))
            {
                Vector2 down = -Vector2.Normalize(triangle.Gradient);
                (t, normal, rises) = (at, new Vector3(down, 0f), true);
            }
        }

        return rises;
    }

    /// <summary>The floor triangle's normal at a floor point found by <see cref="TryFloorBelow"/>.</summary>
    internal Vector3 FloorNormal(float x, float y, float z) =>
        CellSurface.TryFloorNormal(_floors, x, y, z, out Vector3 normal) ? normal : Vector3.UnitZ;
}
