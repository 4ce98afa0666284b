using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.App.Streaming;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using Environment = AcDream.Core.Dat.Environment;

namespace AcDream.App.World;

/// <summary>
/// A scene's world. <see cref="Worlds.Holtburg"/> (the default): synthetic hills on every landblock,
/// flat at the cottage's floor height (94 m) around Holtburg's two buildings, one rock needle too
/// steep to climb, and the 22 real Holtburg cells in landblock 0xA9B4. No real heights are public, so
/// the heights are made up; the height table is non-linear like the game's.
/// <see cref="Worlds.Staircase"/>: landblock 0xF682 (the centre) and the land around it flat at
/// <see cref="StaircaseFlatZ"/>, no cells. Either world serves the objects the scene chose
/// (<see cref="ObjectSets"/>) as the dat would: in the landblock's <see cref="LandBlockInfo"/> or a
/// cell's <see cref="EnvCell.StaticObjects"/>, with the GfxObjs they name.
/// </summary>
internal sealed class HoltburgWorld : ILandblockSource
{
    /// <summary>The worlds a scene may choose (<c>"world"</c>).</summary>
    public static class Worlds
    {
        /// <summary>Holtburg: hills, the needle, the real cells; centre 0xA9B4.</summary>
        public const string Holtburg = "holtburg";

        /// <summary>The outdoor staircase's landblock 0xF682, flat at <see cref="StaircaseFlatZ"/>; centre 0xF682.</summary>
        public const string Staircase = "staircase";
    }

    /// <summary>The object sets a scene may register (<c>"objects"</c>), with the world each stands in.</summary>
    public static readonly IReadOnlyDictionary<string, string> ObjectSets = new Dictionary<string, string>
    {
        ["cottage"] = Worlds.Holtburg,
        ["small-building"] = Worlds.Holtburg,
        ["cellar-stairs"] = Worlds.Holtburg,
        ["staircase"] = Worlds.Staircase,
    };

    /// <summary>The doors a scene may register (<c>"doors"</c>), with the world each stands in.</summary>
    public static readonly IReadOnlyDictionary<string, string> DoorSets = new Dictionary<string, string>
    {
        ["cottage-west"] = Worlds.Holtburg,
    };

    /// <summary>The staircase's landblock.</summary>
    public const uint StaircaseLandblock = ObjectPlacements.StaircaseLandblock;

    /// <summary>Height (metres) of the staircase world's flat land: the first stair piece's origin, so its tread's low edge (59.015 m) is a 0.2 m step up.</summary>
    public const float StaircaseFlatZ = 58.815f;

    /// <summary>Holtburg's landblock, the centre of the scene's world frame.</summary>
    public const uint Holtburg = 0xA9B4FFFFu;

    /// <summary>Height (metres) of the flat ground around the buildings: the cottage's floor.</summary>
    public const float FlatZ = 94f;

    /// <summary>Height index whose table entry is <see cref="FlatZ"/>.</summary>
    public const byte FlatIndex = 64;

    /// <summary>Height index of the needle vertex: 326 m, about 230 m above its neighbours.</summary>
    public const byte NeedleIndex = 160;

    /// <summary>The needle's vertex indices in 0xA9B4: at landblock-local (72, 48) m.</summary>
    public static readonly (int X, int Y) NeedleVertex = (3, 2);

    private static readonly int HoltburgX = CellIds.LandblockX(Holtburg), HoltburgY = CellIds.LandblockY(Holtburg);

    private readonly List<CellFixtureReader.FixtureCell> _cells;
    private readonly Dictionary<uint, Environment> _environments = [];

    private readonly bool _flat;
    private readonly LandBlockInfo? _info;
    private readonly Dictionary<uint, GfxObj> _gfxObjs = [];

    /// <summary>Holtburg with no objects: the world of scenes that choose none.</summary>
    public HoltburgWorld()
        : this(Worlds.Holtburg, [])
    {
    }

    /// <summary>The world <paramref name="world"/> (<see cref="Worlds"/>) with the object sets <paramref name="objects"/> (<see cref="ObjectSets"/>).</summary>
    /// <exception cref="ArgumentException">An unknown world or object set, or a set of another world.</exception>
    public HoltburgWorld(string world, IReadOnlyList<string> objects)
    {
        ArgumentNullException.ThrowIfNull(objects);
        if (world is not (Worlds.Holtburg or Worlds.Staircase))
        {
            throw new ArgumentException($"unknown world \"{world}\".", nameof(world));
        }

        foreach (string set in objects)
        {
            if (!ObjectSets.TryGetValue(set, out string? home) || home != world)
            {
                throw new ArgumentException($"object set \"{set}\" is not one of the {world} world's.", nameof(objects));
            }
        }

        World = world;
        Objects = [.. objects.Distinct()];
        _flat = world == Worlds.Staircase;
        Center = _flat ? StaircaseLandblock : Holtburg;
        _cells = _flat ? [] : HoltburgFixtures.ReadAll();
        foreach (CellFixtureReader.FixtureCell cell in _cells)
        {
            // The fixtures carry no environment ids: each cell gets its own synthetic environment,
            // numbered as the cell (0x0D000145 for 0xA9B40145).
            ushort environmentId = CellIds.CellNumber(cell.CellId);
            cell.EnvCell.EnvironmentId = environmentId;
            cell.EnvCell.CellStructure = 0;
            _environments.Add(0x0D000000u | environmentId, new Environment { Id = 0x0D000000u | environmentId, Cells = { [0] = cell.CellStruct } });
        }

        HeightTable = BuildHeightTable(_flat ? StaircaseFlatZ : FlatZ);
        CellSurfaces = _cells.ConvertAll(c => new CellSurface(c.CellId, c.EnvCell, c.CellStruct));

        if (Objects.Count > 0)
        {
            Dictionary<uint, GfxObj> all = HoltburgFixtures.ReadObjects();
            _info = new LandBlockInfo { Id = (Center & 0xFFFF0000u) | 0xFFFEu };
            foreach (string set in Objects)
            {
                switch (set)
                {
                    case "cottage":
                        _info.Buildings.Add(ObjectPlacements.Cottage());
                        break;
                    case "small-building":
                        _info.Buildings.Add(ObjectPlacements.SmallBuildingShell());
                        break;
                    case "staircase":
                        _info.Objects.AddRange(ObjectPlacements.StaircaseInfo().Objects);
                        break;
                    case "cellar-stairs":
                        foreach ((uint cellId, GfxObj stair, Stab placement) in ObjectPlacements.CellarStairs())
                        {
                            _cells.Single(c => c.CellId == cellId).EnvCell.StaticObjects.Add(placement);
                            all[stair.Id] = stair;
                        }

                        break;
                }
            }

            foreach (uint id in _info.Objects.Select(o => o.Id).Concat(_info.Buildings.Select(b => b.ModelId))
                .Concat(_cells.SelectMany(c => c.EnvCell.StaticObjects).Select(o => o.Id)))
            {
                _gfxObjs[id] = all[id];
            }
        }

        ObjectSurfaces = ObjectSurface.FromLandblock(Center, _info, _cells.ConvertAll(c => c.EnvCell), _gfxObjs, new Dictionary<uint, Setup>());

        var doors = new Dictionary<string, WorldDoor>();
        if (!_flat)
        {
            CellFixtureReader.FixtureCell doorCell = _cells.Single(c => c.CellId == ObjectPlacements.CottageWestDoorCell);
            (GfxObj slab, Vector3 origin, Quaternion orientation) = ObjectPlacements.DoorSlab(doorCell, 0xFFFF, ObjectPlacements.CottageWestDoorSlab);
            doors["cottage-west"] = new WorldDoor("cottage-west", ObjectPlacements.CottageWestDoor, doorCell.CellId, slab, new MoverShape(slab), origin, orientation);
        }

        Doors = doors;
    }

    /// <summary>The world's doors by name (<see cref="DoorSets"/>): built with the world, registered only as a scene chooses them.</summary>
    public IReadOnlyDictionary<string, WorldDoor> Doors { get; }

    /// <summary>The world's name (<see cref="Worlds"/>).</summary>
    public string World { get; }

    /// <summary>The object sets registered (<see cref="ObjectSets"/>), in the scene's order.</summary>
    public IReadOnlyList<string> Objects { get; }

    /// <summary>The landblock whose south-west corner is world (0, 0): 0xA9B4, or 0xF682 in the staircase world. All objects stand in it.</summary>
    public uint Center { get; }

    /// <summary>The engine's surfaces of the objects (all in <see cref="Center"/>), as the engine is given them (built once).</summary>
    public IReadOnlyList<ObjectSurface> ObjectSurfaces { get; }

    /// <summary>Whether this world is the one <paramref name="world"/> with exactly the object sets <paramref name="objects"/>.</summary>
    public bool Is(string world, IReadOnlyList<string> objects) => World == world && Objects.SequenceEqual(objects.Distinct());

    /// <summary>A short name for an object a scene may register, or null.</summary>
    public static string? ObjectName(uint objectId) => objectId switch
    {
        ObjectPlacements.CottageShell => "cottage shell",
        ObjectPlacements.SmallBuilding => "small building",
        ObjectPlacements.StairPiece => "stair piece",
        ObjectPlacements.CottageCellarStair => "cottage cellar stair",
        ObjectPlacements.BuildingBCellarStair => "building B cellar stair",
        ObjectPlacements.CottageWestDoor => "cottage west door",
        _ => null,
    };

    /// <summary>The region's height table: 256 heights in metres, finer steps near the flat height (94 m, or <see cref="StaircaseFlatZ"/> in the staircase world), coarser away from it.</summary>
    public float[] HeightTable { get; }

    /// <summary>The real cells of 0xA9B4, ascending id.</summary>
    public IReadOnlyList<CellFixtureReader.FixtureCell> Cells => _cells;

    /// <summary>The engine's surfaces of <see cref="Cells"/>, in the same order: what the engine is given for 0xA9B4 (built once).</summary>
    public IReadOnlyList<CellSurface> CellSurfaces { get; }

    /// <summary>Table entry i = <paramref name="flatZ"/> + 0.5·d + 0.02·d·|d| metres with d = i − 64: monotonic, <paramref name="flatZ"/> at 64.</summary>
    private static float[] BuildHeightTable(float flatZ)
    {
        var table = new float[256];
        for (int i = 0; i < table.Length; i++)
        {
            float d = i - FlatIndex;
            table[i] = flatZ + (0.5f * d) + (0.02f * d * MathF.Abs(d));
        }

        return table;
    }

    /// <summary>The 81 height indices of a landblock, x-major, from one function of the global vertex coordinates, so seams match.</summary>
    public static byte[] Heights(uint landblockId)
    {
        int lbX = CellIds.LandblockX(landblockId), lbY = CellIds.LandblockY(landblockId);
        var heights = new byte[LandBlock.VertexCount];
        for (int x = 0; x < 9; x++)
        {
            for (int y = 0; y < 9; y++)
            {
                heights[(x * 9) + y] = HeightIndex((lbX * 8) + x, (lbY * 8) + y);
            }
        }

        return heights;
    }

    /// <summary>A short name for a Holtburg cell, or null for other cells.</summary>
    public static string? CellName(uint cellId) => cellId switch
    {
        0xA9B40140u => "cottage, raised doorway",
        0xA9B40141u => "cottage, north room",
        0xA9B40142u => "cottage, raised passage",
        0xA9B40143u => "cottage, main room",
        0xA9B40144u => "cottage, doorway to 0x013F",
        0xA9B40145u => "cottage, west door",
        0xA9B40146u => "cottage, cellar shaft",
        0xA9B40147u => "cottage, cellar",
        0xA9B40148u => "cottage, cellar ramp",
        0xA9B40149u => "cottage, cellar end",
        0xA9B4014Au => "cottage, upper opening",
        0xA9B4014Bu => "cottage, upper floor",
        0xA9B4014Cu => "cottage, north-west door",
        0xA9B4014Du => "cottage, upper floor east",
        0xA9B4014Eu => "cottage, upper door",
        0xA9B4014Fu => "cottage, north door",
        0xA9B40170u => "building B, north door",
        0xA9B40171u => "building B, main room",
        0xA9B40172u => "building B, east room",
        0xA9B40173u => "building B, doorway",
        0xA9B40174u => "building B, cellar",
        0xA9B40175u => "building B, cellar shaft",
        _ => null,
    };

    /// <summary>The game-triangle terrain of a landblock, as the engine gets it.</summary>
    public TerrainSurface Terrain(uint landblockId) => new(HeightsOf(landblockId), HeightTable, CellIds.LandblockOf(landblockId));

    /// <inheritdoc />
    public LoadedLandblock Load(uint landblockId)
    {
        uint id = CellIds.LandblockOf(landblockId);
        var landBlock = new LandBlock { Id = id, Height = HeightsOf(id) };
        return id == Center
            ? new LoadedLandblock(landBlock, _cells.ConvertAll(c => c.EnvCell), _environments, _info, _gfxObjs, new Dictionary<uint, Setup>())
            : new LoadedLandblock(landBlock, [], new Dictionary<uint, Environment>());
    }

    private byte[] HeightsOf(uint landblockId) => _flat ? Enumerable.Repeat(FlatIndex, LandBlock.VertexCount).ToArray() : Heights(landblockId);

    /// <summary>
    /// Height index of global vertex (gx, gy): 64 (94 m) on a rectangle around the buildings
    /// (0xA9B4-local x 96..216 m, y −48..48 m), rolling hills of about ±15 m blending in over 72 m
    /// outside it, and the needle.
    /// </summary>
    private static byte HeightIndex(int gx, int gy)
    {
        if (gx == (HoltburgX * 8) + NeedleVertex.X && gy == (HoltburgY * 8) + NeedleVertex.Y)
        {
            return NeedleIndex;
        }

        // Metres from 0xA9B4's south-west corner.
        double wx = (gx - (HoltburgX * 8)) * 24.0, wy = (gy - (HoltburgY * 8)) * 24.0;
        double dx = Math.Max(0, Math.Max(96 - wx, wx - 216)), dy = Math.Max(0, Math.Max(-48 - wy, wy - 48));
        double t = Math.Clamp(Math.Sqrt((dx * dx) + (dy * dy)) / 72.0, 0, 1);
        double weight = t * t * (3 - (2 * t));
        double hill = (14 * Math.Sin((wx / 70) + 0.3) * Math.Cos(wy / 55))
            + (9 * Math.Sin((wx - (2 * wy)) / 110))
            + (5 * Math.Cos((wx / 33) - (wy / 41)));
        return (byte)Math.Clamp(FlatIndex + (int)Math.Round(weight * hill), 0, 255);
    }
}
