using AcDream.Core.Physics;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>Terrain Z: the spec's bilinear patch vs the game's two triangles per cell, same heights and points.</summary>
[MemoryDiagnoser]
public class SampleZBenchmarks
{
    private const int Queries = 1024;

    private TerrainSurface _bilinear = null!;
    private TerrainSurface _triangles = null!;
    private float[] _x = null!;
    private float[] _y = null!;

    [GlobalSetup]
    public void Setup()
    {
        var random = new Random(5);
        byte[] heights = World.RollingHeights(random, 60, 8);
        float[] table = World.NonLinearTable();
        _bilinear = new TerrainSurface(heights, table);
        _triangles = new TerrainSurface(heights, table, World.Holtburg);
        _x = new float[Queries];
        _y = new float[Queries];
        for (int i = 0; i < Queries; i++)
        {
            _x[i] = random.NextSingle() * 192f;
            _y[i] = random.NextSingle() * 192f;
        }
    }

    [Benchmark(Baseline = true, OperationsPerInvoke = Queries)]
    public float Bilinear() => Sum(_bilinear);

    [Benchmark(OperationsPerInvoke = Queries)]
    public float Triangles() => Sum(_triangles);

    private float Sum(TerrainSurface terrain)
    {
        float sum = 0f;
        float[] x = _x, y = _y;
        for (int i = 0; i < x.Length; i++)
        {
            sum += terrain.SampleZ(x[i], y[i]);
        }

        return sum;
    }
}
