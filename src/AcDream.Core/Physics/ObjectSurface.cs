using System.Numerics;
using AcDream.Core.Dat;

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
public sealed class ObjectSurface
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
    /// Whether a floor of this object rises through height <paramref name="h"/> (a point mover's feet plus its step)
    /// on the move <paramref name="p0"/> → <paramref name="p1"/> (landblock-local; box <paramref name="lo"/>–<paramref name="hi"/>)
    /// before fraction <paramref name="t"/>: the move comes from where the floor's plane is at or below that line to
    /// where it is above it, crossing it within the floor. The mover would pass under a floor (a ramp rising ahead
    /// of it) that its step line runs into, so it is stopped there as by a rise too high: <paramref name="t"/> is
    /// where, <paramref name="normal"/> the horizontal unit normal facing the mover (down the slope).
    /// </summary>
    internal bool RisesThrough(Vector2 p0, Vector2 p1, Vector2 lo, Vector2 hi, float h, ref float t, ref Vector3 normal)
    {
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

    private static ObjectSurface FromStab(Stab stab, uint cellId, IReadOnlyDictionary<uint, GfxObj> gfxObjs, IReadOnlyDictionary<uint, Setup> setups)
    {
        ArgumentNullException.ThrowIfNull(stab);
        return new ObjectSurface(stab.Id, cellId, PlaceModel(stab.Id, stab.Frame, gfxObjs, setups, "stab"), isBuilding: false, []);
    }

    private static Placed PlaceModel(uint id, Frame frame, IReadOnlyDictionary<uint, GfxObj> gfxObjs, IReadOnlyDictionary<uint, Setup> setups, string argument)
    {
        if (id >> 24 == 0x01 && gfxObjs.TryGetValue(id, out GfxObj? gfxObj))
        {
            return Place(gfxObj, frame);
        }

        if (id >> 24 == 0x02 && setups.TryGetValue(id, out Setup? setup))
        {
            return Place(setup, gfxObjs, frame);
        }

        throw new ArgumentException(
            id >> 24 is 0x01 or 0x02 ? $"{Name(id)}: not found among the {(id >> 24 == 0x01 ? "GfxObjs" : "Setups")} given."
            : $"{Name(id)}: not a GfxObj (0x01xxxxxx) or Setup (0x02xxxxxx) id.",
            argument);
    }

    private static Placed Place(GfxObj gfxObj, Frame frame)
    {
        ArgumentNullException.ThrowIfNull(gfxObj);
        var placed = new Placed(Name(gfxObj.Id), Rigid.Of(Name(gfxObj.Id), frame, "frame"));
        placed.AddPart(gfxObj, Vector3.One, Rigid.Identity);
        return placed;
    }

    private static Placed Place(Setup setup, IReadOnlyDictionary<uint, GfxObj> gfxObjs, Frame frame)
    {
        ArgumentNullException.ThrowIfNull(setup);
        ArgumentNullException.ThrowIfNull(gfxObjs);
        string name = Name(setup.Id);
        var placed = new Placed(name, Rigid.Of(name, frame, "frame"));
        List<uint> parts = setup.Parts ?? throw new ArgumentNullException(nameof(setup), $"{name}: setup.Parts is null.");
        List<Vector3> scales = setup.DefaultScale ?? [];
        List<Frame>? pose = setup.PlacementFrames is { } frames && frames.TryGetValue(Placement.Default, out AnimationFrame? animation) ? animation?.Frames : null;
        if (scales.Count != 0 && scales.Count != parts.Count)
        {
            throw new ArgumentException($"{name}: {scales.Count} default scales for {parts.Count} parts.", nameof(setup));
        }

        if (pose is not null && pose.Count != parts.Count)
        {
            throw new ArgumentException($"{name}: the default pose has {pose.Count} frames for {parts.Count} parts.", nameof(setup));
        }

        for (int i = 0; i < parts.Count; i++)
        {
            if (!gfxObjs.TryGetValue(parts[i], out GfxObj? part))
            {
                throw new ArgumentException($"{name}: part {i} (0x{parts[i]:X8}) is not among the GfxObjs given.", nameof(gfxObjs));
            }

            Vector3 scale = scales.Count == 0 ? Vector3.One : scales[i];
            if (!float.IsFinite(scale.X) || !float.IsFinite(scale.Y) || !float.IsFinite(scale.Z))
            {
                throw new ArgumentException($"{name}: part {i} has scale {scale}; scales must be finite.", nameof(setup));
            }

            placed.AddPart(part, scale, pose is null ? Rigid.Identity : Rigid.Of($"{name} part {i}", pose[i], nameof(setup)));
        }

        foreach ((CylSphere? cylinder, int i) in (setup.CylSpheres ?? []).Select((c, i) => (c, i)))
        {
            if (cylinder is null || !Geometry.IsFinite(cylinder.Origin) || !float.IsFinite(cylinder.Radius) || !float.IsFinite(cylinder.Height)
                || cylinder.Radius < 0f || cylinder.Height < 0f)
            {
                throw new ArgumentException(
                    $"{name}: cylinder {i} ({cylinder?.Origin}, radius {cylinder?.Radius}, height {cylinder?.Height}) must be finite with a radius and height ≥ 0.",
                    nameof(setup));
            }

            placed.AddCylinder(cylinder.Origin, cylinder.Radius, cylinder.Height);
        }

        return placed;
    }

    /// <summary>The model's id (null: the model is null), checked to be of <paramref name="kind"/> (its top byte).</summary>
    private static uint CheckedId(uint? id, uint kind, string argument)
    {
        if (id is not uint value)
        {
            throw new ArgumentNullException(argument);
        }

        if (value >> 24 != kind)
        {
            throw new ArgumentException($"{Name(value)}: not a {(kind == 0x01 ? "GfxObj (0x01xxxxxx)" : "Setup (0x02xxxxxx)")} id.", argument);
        }

        return value;
    }

    private static string Name(uint id) => $"object 0x{id:X8}";


    /// <summary>A rotation and translation, the rotation a unit quaternion.</summary>
    private readonly record struct Rigid(Quaternion Rotation, Vector3 Origin)
    {
        public static Rigid Identity => new(Quaternion.Identity, Vector3.Zero);

        public static Rigid Of(string name, Frame? frame, string argument)
        {
            if (frame is null)
            {
                throw new ArgumentNullException(argument, $"{name}: the frame is null.");
            }

            if (!Geometry.IsFinite(frame.Origin) || !CellSurface.TryUnitOrientation(frame.Orientation, out Quaternion unit))
            {
                throw new ArgumentException($"{name}: frame ({frame.Origin}, {frame.Orientation}) is not a placement (non-finite, or an orientation shorter than 1e-6).", argument);
            }

            return new Rigid(unit, frame.Origin);
        }

        public Vector3 Apply(Vector3 v) => Origin + Vector3.Transform(v, Rotation);
    }

    /// <summary>The placed physics polygons (each with its winding normal) and cylinders of one object, landblock-local.</summary>
    private sealed class Placed(string name, Rigid frame)
    {
        /// <summary>A copy moved by <paramref name="offset"/>.</summary>
        public Placed Shifted(Vector3 offset)
        {
            var moved = new Placed(name, frame);
            foreach ((ushort id, Vector3[] v, Vector3 n) in Polygons)
            {
                moved.Polygons.Add((id, Array.ConvertAll(v, p => p + offset), n));
            }

            foreach ((Vector3 b, float r, float h) in Cylinders)
            {
                moved.Cylinders.Add((b + offset, r, h));
            }

            return moved;
        }

        public List<(ushort Id, Vector3[] Vertices, Vector3 Normal)> Polygons { get; } = [];

        public List<(Vector3 Base, float Radius, float Height)> Cylinders { get; } = [];

        public void AddPart(GfxObj part, Vector3 scale, Rigid partFrame)
        {
            string what = part.Id == 0 ? name : $"{name} (part 0x{part.Id:X8})";
            Dictionary<ushort, Polygon> polygons = part.PhysicsPolygons
                ?? throw new ArgumentNullException("gfxObj", $"{what}: PhysicsPolygons is null.");
            Dictionary<ushort, SWVertex> vertices = part.VertexArray?.Vertices
                ?? throw new ArgumentNullException("gfxObj", $"{what}: VertexArray.Vertices is null.");
            var keys = new List<ushort>(polygons.Keys);
            keys.Sort();
            foreach (ushort key in keys)
            {
                List<short> ids = polygons[key]?.VertexIds
                    ?? throw new ArgumentNullException("gfxObj", $"{what}: physics polygon {key} or its VertexIds is null.");
                if (ids.Count < 3)
                {
                    throw new ArgumentException($"{what}: physics polygon {key} has {ids.Count} vertices; a polygon needs at least 3.", "gfxObj");
                }

                var v = new Vector3[ids.Count];
                for (int i = 0; i < v.Length; i++)
                {
                    if (ids[i] < 0 || !vertices.TryGetValue((ushort)ids[i], out SWVertex? vertex) || vertex is null)
                    {
                        throw new ArgumentException($"{what}: physics polygon {key} names vertex {ids[i]}, which the vertex array lacks.", "gfxObj");
                    }

                    if (!Geometry.IsFinite(vertex.Origin))
                    {
                        throw new ArgumentException($"{what}: vertex {ids[i]} (physics polygon {key}) is {vertex.Origin}; vertices must be finite.", "gfxObj");
                    }

                    v[i] = Checked(frame.Apply(partFrame.Apply(vertex.Origin * scale)), $"{what}: vertex {ids[i]} (physics polygon {key})");
                }

                Polygons.Add((key, v, Geometry.NewellNormal(v, v[0])));
            }
        }

        public void AddCylinder(Vector3 origin, float radius, float height) =>
            Cylinders.Add((Checked(frame.Apply(origin), $"{name}: a cylinder"), radius, height));

        public (Vector3 Min, Vector3 Max) Bounds()
        {
            Vector3 min = new(float.MaxValue), max = new(float.MinValue);
            foreach ((_, Vector3[] v, _) in Polygons)
            {
                foreach (Vector3 p in v)
                {
                    (min, max) = (Vector3.Min(min, p), Vector3.Max(max, p));
                }
            }

            foreach ((Vector3 b, float r, float h) in Cylinders)
            {
                (min, max) = (Vector3.Min(min, b - new Vector3(r, r, 0f)), Vector3.Max(max, b + new Vector3(r, r, h)));
            }

            return min.X <= max.X ? (min, max) : (Vector3.Zero, Vector3.Zero);
        }

        private static Vector3 Checked(Vector3 p, string what)
        {
            const float limit = PhysicsConstants.MaxCellCoordinate;
            if (!(MathF.Abs(p.X) <= limit && MathF.Abs(p.Y) <= limit && MathF.Abs(p.Z) <= limit))
            {
                throw new ArgumentException($"{what} is placed at {p}, farther than {limit} m from the landblock.", "frame");
            }

            return p;
        }
    }
}

/// <summary>One wall of an <see cref="ObjectSurface"/> seen by a caller: a polygon's outline (landblock-local metres), or a cylinder (<see cref="Radius"/> > 0: its axis from bottom to top).</summary>
/// <param name="Outline">The polygon's vertices, or a cylinder's bottom and top centre.</param>
/// <param name="Radius">0 for a polygon; a cylinder's radius, metres.</param>
public sealed record ObjectWallInfo(Vector3[] Outline, float Radius);
