using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using AcDream.App.Fixtures;

namespace AcDream.Core.Tests;

/// <summary>Small builders for fake dat data.</summary>
internal static class TestData
{
    public const uint Holtburg = 0xA9B4FFFFu;

    /// <summary>A linear height table: index i → 2·i metres.</summary>
    public static float[] LinearTable()
    {
        var table = new float[256];
        for (int i = 0; i < 256; i++)
        {
            table[i] = 2f * i;
        }

        return table;
    }

    /// <summary>A non-linear table like the game's: fine steps low, coarse steps high (metres).</summary>
    public static float[] NonLinearTable()
    {
        var table = new float[256];
        for (int i = 0; i < 256; i++)
        {
            table[i] = (0.5f * i) + (0.02f * i * i);
        }

        return table;
    }

    /// <summary>A table whose every index gives <paramref name="z"/> metres.</summary>
    public static float[] ConstantTable(float z) => Enumerable.Repeat(z, 256).ToArray();

    public static byte[] FlatHeights(byte value) => Enumerable.Repeat(value, 81).ToArray();

    /// <summary>Heights from a function of the vertex indices (x, y), x-major.</summary>
    public static byte[] Heights(Func<int, int, int> height) => CellBuilder.Heights(height);

    public static byte[] RandomHeights(Random random)
    {
        var heights = new byte[81];
        random.NextBytes(heights);
        return heights;
    }

    /// <summary>Flat terrain at <paramref name="z"/> metres for a landblock.</summary>
    public static TerrainSurface FlatTerrain(float z, uint landblockId = Holtburg) =>
        new(FlatHeights(0), ConstantTable(z), landblockId);

    /// <summary>A horizontal square floor polygon, counter-clockwise from above (cell-local).</summary>
    public static Vector3[] Square(float minX, float minY, float maxX, float maxY, float z) => CellBuilder.Square(minX, minY, maxX, maxY, z);

    /// <summary>A vertical wall from (x0, y0) to (x1, y1), from z0 up to z1.</summary>
    public static Vector3[] Wall(float x0, float y0, float x1, float y1, float z0, float z1) =>
        [new(x0, y0, z0), new(x1, y1, z0), new(x1, y1, z1), new(x0, y0, z1)];
}

/// <summary>The real Holtburg cells of <c>Fixtures/holtburg-cells</c>.</summary>
internal static class HoltburgCells
{
    private static readonly Lazy<IReadOnlyDictionary<uint, CellFixtureReader.FixtureCell>> All = new(Load);

    public static IReadOnlyDictionary<uint, CellFixtureReader.FixtureCell> Fixtures => All.Value;

    public static CellSurface Surface(uint cellId)
    {
        CellFixtureReader.FixtureCell cell = Fixtures[cellId];
        return new CellSurface(cell.CellId, cell.EnvCell, cell.CellStruct);
    }

    public static List<CellSurface> Surfaces() => Fixtures.Keys.Order().Select(Surface).ToList();

    /// <summary>
    /// A random start for the engine of <see cref="OnHills"/> (world <paramref name="origin"/> is Holtburg's corner): in
    /// one of <paramref name="cells"/> over the cottages' footprint, or outdoors anywhere in the landblock; 85–145 m up.
    /// </summary>
    public static (Vector3 Position, uint Cell) RandomStart(Random random, Vector3 origin, uint[] cells, bool indoor)
    {
        uint cell = indoor ? cells[random.Next(cells.Length)] : 0xA9B40000u;
        var position = origin + new Vector3(
            indoor ? 124 + (float)(random.NextDouble() * 42) : (float)(random.NextDouble() * 192),
            indoor ? -1 + (float)(random.NextDouble() * 21) : (float)(random.NextDouble() * 192),
            85 + (float)(random.NextDouble() * 60));
        return (position, cell);
    }

    /// <summary>
    /// The real cells on random hills (height index 150–199 at random, 188 on the vertices x 5–6, y 0–1; the
    /// non-linear table) with the south neighbour flat at 94 m, in the global frame or one centred on Holtburg.
    /// </summary>
    public static (PhysicsEngine Engine, TerrainSurface Terrain) OnHills(Random random, string frame)
    {
        byte[] heights = TestData.Heights((x, y) => x is >= 5 and <= 6 && y <= 1 ? 188 : random.Next(150, 200));
        var terrain = new TerrainSurface(heights, TestData.NonLinearTable(), TestData.Holtburg);
        PhysicsEngine engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(TestData.Holtburg);
        engine.AddLandblock(TestData.Holtburg, terrain, Surfaces());
        engine.AddLandblock(0xA9B3FFFFu, TestData.FlatTerrain(94f, 0xA9B3FFFFu), []);
        return (engine, terrain);
    }

    private static Dictionary<uint, CellFixtureReader.FixtureCell> Load()
    {
        string folder = Path.Combine(AppContext.BaseDirectory, "Fixtures", "holtburg-cells");
        return Directory.GetFiles(folder, "*.json")
            .Select(path => CellFixtureReader.Read(File.ReadAllText(path), path))
            .ToDictionary(cell => cell.CellId);
    }
}

/// <summary>The real objects of <c>Fixtures/objects</c> and their recorded placements.</summary>
internal static class RealObjects
{
    private static readonly Lazy<IReadOnlyDictionary<uint, GfxObj>> All = new(Load);

    /// <summary>The fixture GfxObjs by id (shared: do not change them).</summary>
    public static IReadOnlyDictionary<uint, GfxObj> GfxObjs => All.Value;

    public static IReadOnlyDictionary<uint, Setup> NoSetups { get; } = new Dictionary<uint, Setup>();

    /// <summary>Landblock 0xA9B4's buildings (the cottage's shell and the small building) as surfaces.</summary>
    public static List<ObjectSurface> HoltburgBuildings() =>
        ObjectSurface.FromLandblock(TestData.Holtburg, ObjectPlacements.HoltburgInfo(), [], GfxObjs, NoSetups);

    /// <summary>
    /// Holtburg as a host registers it with the cellar stairs: the real cells, the buildings, the stairs as the
    /// cellars' static objects, on flat terrain at 94 m, and the landblock south of it; in the global frame or centred
    /// on Holtburg.
    /// </summary>
    public static PhysicsEngine HoltburgWithCellarStairs(string frame)
    {
        PhysicsEngine engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(TestData.Holtburg);
        var gfxObjs = new Dictionary<uint, GfxObj>(GfxObjs);
        var cells = new List<EnvCell>();
        foreach ((uint cellId, GfxObj stair, Stab placement) in ObjectPlacements.CellarStairs())
        {
            gfxObjs.Add(stair.Id, stair);
            cells.Add(new EnvCell { Id = cellId, StaticObjects = [placement] });
        }

        List<ObjectSurface> objects = ObjectSurface.FromLandblock(TestData.Holtburg, ObjectPlacements.HoltburgInfo(), cells, gfxObjs, NoSetups);
        engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(94f), HoltburgCells.Surfaces(), objects);
        engine.AddLandblock(0xA9B3FFFFu, TestData.FlatTerrain(94f, 0xA9B3FFFFu), []);
        return engine;
    }

    /// <summary>The eight stair pieces of landblock 0xF682.</summary>
    public static List<ObjectSurface> Staircase() =>
        ObjectSurface.FromLandblock(ObjectPlacements.StaircaseLandblock, ObjectPlacements.StaircaseInfo(), [], GfxObjs, NoSetups);

    private static Dictionary<uint, GfxObj> Load()
    {
        string folder = Path.Combine(AppContext.BaseDirectory, "Fixtures", "objects");
        return Directory.GetFiles(folder, "0x*.json")
            .Select(path => ObjectFixtureReader.Read(File.ReadAllText(path), path))
            .ToDictionary(o => o.Id);
    }
}
