using System.Numerics;
using AcDream.Core.Physics;
using BenchmarkDotNet.Attributes;
using BenchmarkDotNet.Configs;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// Building a <see cref="CellSurface"/> and querying its floor (<see cref="CellSurface.SampleFloorZ(float, float, float)"/>,
/// 1,024 random points per call) for real-size cells and a pathological one: 8 and 100 and 1,000
/// polygons laid out as in <see cref="SampleFloorZBenchmarks"/> (1 m squares, a grid turned 30°), and
/// two hard ones: a flat 1,000-vertex circle of radius 10 m (996 fan triangles, long and thin, most
/// overlapping much of the cell; points over its 20 m bounding square, reference Z within 1 m of
/// it) and 8,000 stacked 10 m floors 0.25 m apart (16,000 triangles, each covering the whole cell). The
/// baseline of each category is code this work leaves untouched, so ratios compare across commits:
/// building a <see cref="TerrainSurface"/>, and 1,024 <see cref="TerrainSurface.SampleZ"/> calls.
/// </summary>
[MemoryDiagnoser]
[GroupBenchmarksBy(BenchmarkLogicalGroupRule.ByCategory)]
[CategoriesColumn]
public class FloorGridBenchmarks
{
    private const int Queries = 1024;

    private byte[] _heights = null!;
    private float[] _table = null!;
    private TerrainSurface _terrain = null!;
    private float[] _terrainX = null!;
    private float[] _terrainY = null!;

    private readonly Dictionary<string, (CellBuilder Builder, CellSurface Cell, float[] X, float[] Y, float[] Z)> _cells = [];

    [GlobalSetup]
    public void Setup()
    {
        var random = new Random(5);
        foreach (int polygons in new[] { 8, 100, 1000 })
        {
            int columns = (int)Math.Ceiling(Math.Sqrt(polygons));
            int rows = (polygons + columns - 1) / columns;
            var origin = new Vector3(100f, 50f, 40f);
            Quaternion yaw = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 6);
            var builder = new CellBuilder(0xA9B40100u, origin, yaw);
            for (int i = 0; i < polygons; i++)
            {
                float x = i % columns, y = i / columns;
                builder.Floor(x, y, x + 1, y + 1, random.Next(0, 4) * 0.25f);
            }

            Add($"real{polygons}", builder, random, i =>
            {
                Vector3 p = origin + Vector3.Transform(new Vector3(random.NextSingle() * columns, random.NextSingle() * rows, 0f), yaw);
                return (p.X, p.Y, origin.Z + 0.5f);
            });
        }

        var fan = new CellBuilder(0xA9B40100u, new Vector3(60f, 60f, 10f));
        var circle = new Vector3[1000];
        for (int i = 0; i < circle.Length; i++)
        {
            float angle = i * MathF.Tau / circle.Length;
            circle[i] = new Vector3(10f * MathF.Cos(angle), 10f * MathF.Sin(angle), 0f);
        }

        fan.Physics(circle);
        Add("fan1000", fan, random, i => (50f + (random.NextSingle() * 20f), 50f + (random.NextSingle() * 20f), 9f + (random.NextSingle() * 2f)));

        var stacked = new CellBuilder(0xA9B40100u, new Vector3(20f, 30f, 5f));
        for (int i = 0; i < 8000; i++)
        {
            stacked.Floor(0f, 0f, 10f, 10f, i * 0.25f);
        }

        Add("stacked8000", stacked, random, i => (20f + (random.NextSingle() * 10f), 30f + (random.NextSingle() * 10f), 5f + (random.NextSingle() * 2000f)));

        _heights = World.RollingHeights(random, 60, 6);
        _table = World.NonLinearTable();
        _terrain = new TerrainSurface(_heights, _table, World.Holtburg);
        _terrainX = new float[Queries];
        _terrainY = new float[Queries];
        for (int i = 0; i < Queries; i++)
        {
            _terrainX[i] = random.NextSingle() * 192f;
            _terrainY[i] = random.NextSingle() * 192f;
        }
    }

    [Benchmark(Baseline = true)]
    [BenchmarkCategory("Build")]
    public uint BuildTerrain() => new TerrainSurface(_heights, _table, World.Holtburg).ComputeOutdoorCellId(1f, 1f);

    [Benchmark]
    [BenchmarkCategory("Build")]
    public int BuildReal8() => Build("real8");

    [Benchmark]
    [BenchmarkCategory("Build")]
    public int BuildReal100() => Build("real100");

    [Benchmark]
    [BenchmarkCategory("Build")]
    public int BuildReal1000() => Build("real1000");

    [Benchmark]
    [BenchmarkCategory("Build")]
    public int BuildFan1000() => Build("fan1000");

    [Benchmark]
    [BenchmarkCategory("Build")]
    public int BuildStacked8000() => Build("stacked8000");

    [Benchmark(Baseline = true, OperationsPerInvoke = Queries)]
    [BenchmarkCategory("Query")]
    public float QueryTerrain()
    {
        float sum = 0f;
        TerrainSurface terrain = _terrain;
        float[] x = _terrainX, y = _terrainY;
        for (int i = 0; i < x.Length; i++)
        {
            sum += terrain.SampleZ(x[i], y[i]);
        }

        return sum;
    }

    [Benchmark(OperationsPerInvoke = Queries)]
    [BenchmarkCategory("Query")]
    public float QueryReal8() => Query("real8");

    [Benchmark(OperationsPerInvoke = Queries)]
    [BenchmarkCategory("Query")]
    public float QueryReal100() => Query("real100");

    [Benchmark(OperationsPerInvoke = Queries)]
    [BenchmarkCategory("Query")]
    public float QueryReal1000() => Query("real1000");

    [Benchmark(OperationsPerInvoke = Queries)]
    [BenchmarkCategory("Query")]
    public float QueryFan1000() => Query("fan1000");

    [Benchmark(OperationsPerInvoke = Queries)]
    [BenchmarkCategory("Query")]
    public float QueryStacked8000() => Query("stacked8000");

    private void Add(string name, CellBuilder builder, Random random, Func<int, (float X, float Y, float Z)> point)
    {
        var x = new float[Queries];
        var y = new float[Queries];
        var z = new float[Queries];
        for (int i = 0; i < Queries; i++)
        {
            (x[i], y[i], z[i]) = point(i);
        }

        _cells[name] = (builder, builder.Build(), x, y, z);
    }

    private int Build(string name)
    {
        CellBuilder builder = _cells[name].Builder;
        return new CellSurface(builder.CellId, builder.EnvCell, builder.CellStruct).Portals.Count;
    }

    private float Query(string name)
    {
        (_, CellSurface cell, float[] x, float[] y, float[] z) = _cells[name];
        float sum = 0f;
        for (int i = 0; i < x.Length; i++)
        {
            sum += cell.SampleFloorZ(x[i], y[i], z[i]) ?? 0f;
        }

        return sum;
    }
}
