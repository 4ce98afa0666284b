using AcDream.App.Fixtures;
using AcDream.Core.Physics;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// Registering a landblock with 16 cells (the first 16 real Holtburg cells): building the surfaces
/// from the dat model (16 <see cref="CellSurface"/>s and the <see cref="TerrainSurface"/>) and
/// <see cref="PhysicsEngine.AddLandblock"/>, together and apart. Since issue 10 building a cell also
/// builds its walls (<c>CellWalls</c>) and adding a landblock its wall buckets.
/// </summary>
[MemoryDiagnoser]
public class AddLandblockBenchmarks
{
    private List<CellFixtureReader.FixtureCell> _fixtures = null!;
    private List<CellSurface> _surfaces = null!;
    private TerrainSurface _terrain = null!;
    private byte[] _heights = null!;
    private float[] _table = null!;
    private PhysicsEngine _engine = null!;

    [GlobalSetup]
    public void Setup()
    {
        var random = new Random(5);
        _fixtures = World.HoltburgFixtures().Take(16).ToList();
        _surfaces = World.Surfaces(_fixtures);
        _heights = World.RollingHeights(random, 60, 6);
        _table = World.NonLinearTable();
        _terrain = new TerrainSurface(_heights, _table, World.Holtburg);
        _engine = new PhysicsEngine(World.Holtburg);
    }

    [Benchmark(Baseline = true)]
    public int BuildSurfacesAndAdd() => BuildAndAdd(_engine, _fixtures, _heights, _table);

    /// <summary>
    /// The cells' surfaces and the terrain built from the dat model and added as landblock
    /// <see cref="World.Holtburg"/>: this class's baseline, and <see cref="ObjectAddLandblockBenchmarks"/>'.
    /// </summary>
    internal static int BuildAndAdd(PhysicsEngine engine, List<CellFixtureReader.FixtureCell> fixtures, byte[] heights, float[] table)
    {
        var cells = new CellSurface[fixtures.Count];
        for (int i = 0; i < cells.Length; i++)
        {
            CellFixtureReader.FixtureCell f = fixtures[i];
            cells[i] = new CellSurface(f.CellId, f.EnvCell, f.CellStruct);
        }

        engine.AddLandblock(World.Holtburg, new TerrainSurface(heights, table, World.Holtburg), cells);
        return engine.LandblockCount;
    }

    [Benchmark]
    public int BuildSurfacesOnly()
    {
        int triangles = 0;
        for (int i = 0; i < _fixtures.Count; i++)
        {
            CellFixtureReader.FixtureCell f = _fixtures[i];
            triangles += new CellSurface(f.CellId, f.EnvCell, f.CellStruct).Portals.Count;
        }

        return triangles + (new TerrainSurface(_heights, _table, World.Holtburg).LandblockId is null ? 0 : 1);
    }

    [Benchmark]
    public int AddOnly()
    {
        _engine.AddLandblock(World.Holtburg, _terrain, _surfaces);
        return _engine.LandblockCount;
    }

    /// <summary>
    /// Building the terrain alone: code no issue since issue 5 has changed, so comparing another row's
    /// ratio to it across two builds (run back to back) cancels part of the machine's drift.
    /// </summary>
    [Benchmark]
    public int TerrainOnly() => new TerrainSurface(_heights, _table, World.Holtburg).LandblockId is null ? 0 : 1;
}
