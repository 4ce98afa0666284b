using System.Numerics;
using AcDream.Core.Physics;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// <see cref="CellSurface.SampleFloorZ(float, float, float)"/> on one cell of N square floor
/// polygons (1 m, each at its own height, a grid turned 30° in its landblock), random points over
/// the cell's bounds: how the query scales with the polygon count.
/// </summary>
[MemoryDiagnoser]
public class SampleFloorZBenchmarks
{
    private const int Queries = 1024;

    private CellSurface _cell = null!;
    private float[] _x = null!;
    private float[] _y = null!;
    private float[] _z = null!;

    [Params(4, 20, 100, 1000)]
    public int Polygons { get; set; }

    [GlobalSetup]
    public void Setup()
    {
        var random = new Random(5);
        int columns = (int)Math.Ceiling(Math.Sqrt(Polygons));
        int rows = (Polygons + columns - 1) / columns;
        var origin = new Vector3(100f, 50f, 40f);
        Quaternion yaw = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 6);
        var builder = new CellBuilder(0xA9B40100u, origin, yaw);
        for (int i = 0; i < Polygons; i++)
        {
            float x = i % columns, y = i / columns;
            builder.Floor(x, y, x + 1, y + 1, random.Next(0, 4) * 0.25f);
        }

        _cell = builder.Build();
        _x = new float[Queries];
        _y = new float[Queries];
        _z = new float[Queries];
        for (int i = 0; i < Queries; i++)
        {
            var local = new Vector3(random.NextSingle() * columns, random.NextSingle() * rows, 0f);
            Vector3 p = origin + Vector3.Transform(local, yaw);
            _x[i] = p.X;
            _y[i] = p.Y;
            _z[i] = origin.Z + 0.5f;
        }
    }

    [Benchmark(OperationsPerInvoke = Queries)]
    public float SampleFloorZ()
    {
        float sum = 0f;
        CellSurface cell = _cell;
        for (int i = 0; i < _x.Length; i++)
        {
            sum += cell.SampleFloorZ(_x[i], _y[i], _z[i]) ?? 0f;
        }

        return sum;
    }
}
