using System.Numerics;
using AcDream.Core.Physics;
using BenchmarkDotNet.Attributes;
using BenchmarkDotNet.Configs;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// Many movers at once (issue 9): one batch of 65,536 frame moves (0.1..0.3 m, the literal call),
/// half outdoors anywhere on Holtburg (flat at the cottages' floor height, so some walk into them)
/// and half indoors on the 22 real Holtburg cells, resolved on one thread (the baseline) and split
/// in two halves on two threads (the calling thread and one task). The ratio of the two is the
/// speed-up of concurrent resolving; per-call times, as <c>OperationsPerInvoke</c> is the batch.
/// The <c>Ceiling</c> pair splits a loop of pure arithmetic (no memory) the same way: what two
/// threads gain on this machine at the time of the run, whatever the code. On a 2-vCPU machine
/// shared with other builds it falls to 1× when another process holds a core.
/// </summary>
[MemoryDiagnoser]
[GroupBenchmarksBy(BenchmarkLogicalGroupRule.ByCategory)]
[CategoriesColumn]
public class ThroughputBenchmarks
{
    private const int Moves = 65_536;

    private readonly Vector3[] _positions = new Vector3[Moves];
    private readonly uint[] _cellIds = new uint[Moves];
    private readonly Vector3[] _deltas = new Vector3[Moves];
    private PhysicsEngine _engine = null!;

    [GlobalSetup]
    public void Setup()
    {
        var random = new Random(5);
        var fixtures = World.HoltburgFixtures();
        List<CellSurface> surfaces = World.Surfaces(fixtures);
        _engine = new PhysicsEngine(World.Holtburg);
        _engine.AddLandblock(World.Holtburg, new TerrainSurface(new byte[81], World.ConstantTable(World.HoltburgGroundZ), World.Holtburg), surfaces);
        _engine.AddLandblock(0xA9B3FFFFu, new TerrainSurface(new byte[81], World.ConstantTable(World.HoltburgGroundZ), 0xA9B3FFFFu), []);

        for (int i = 0; i < Moves;)
        {
            if (i % 2 == 0)
            {
                float x = 4f + (random.NextSingle() * 184f), y = 4f + (random.NextSingle() * 184f);
                _positions[i] = new Vector3(x, y, World.HoltburgGroundZ);
                _cellIds[i] = (World.Holtburg & 0xFFFF0000u) | World.OutdoorCell(x, y);
            }
            else
            {
                int c = random.Next(fixtures.Count);
                (Vector2 min, Vector2 max) = World.Bounds(fixtures[c]);
                float x = min.X + (random.NextSingle() * (max.X - min.X)), y = min.Y + (random.NextSingle() * (max.Y - min.Y));
                if (surfaces[c].SampleFloorZ(x, y) is not float z)
                {
                    continue; // no floor there (a wall's footprint, a shaft): draw again
                }

                _positions[i] = new Vector3(x, y, z);
                _cellIds[i] = surfaces[c].CellId;
            }

            _deltas[i] = World.RandomDelta(random, 0.1f, 0.3f);
            i++;
        }
    }

    [Benchmark(Baseline = true, OperationsPerInvoke = Moves)]
    [BenchmarkCategory("Resolve")]
    public float OneThread() => Run(0, Moves);

    [Benchmark(OperationsPerInvoke = Moves)]
    [BenchmarkCategory("Resolve")]
    public float TwoThreads()
    {
        Task<float> second = Task.Run(() => Run(Moves / 2, Moves));
        float first = Run(0, Moves / 2);
        return first + second.Result;
    }

    [Benchmark(Baseline = true, OperationsPerInvoke = Moves)]
    [BenchmarkCategory("Ceiling")]
    public ulong ArithmeticOneThread() => Spin(1, Moves);

    [Benchmark(OperationsPerInvoke = Moves)]
    [BenchmarkCategory("Ceiling")]
    public ulong ArithmeticTwoThreads()
    {
        Task<ulong> second = Task.Run(() => Spin(7, Moves / 2));
        return Spin(3, Moves / 2) + second.Result;
    }

    /// <summary>About 70 ns of xorshift per step, in registers only.</summary>
    private static ulong Spin(ulong x, int steps)
    {
        for (int i = 0; i < steps * 40; i++)
        {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
        }

        return x;
    }

    private float Run(int from, int to)
    {
        float sum = 0f;
        for (int i = from; i < to; i++)
        {
            ResolveResult r = _engine.Resolve(_positions[i], _cellIds[i], _deltas[i], World.PlayerStepUp);
            sum += r.Position.X + r.Position.Z + r.CellId + (r.IsOnGround ? 1f : 0f);
        }

        return sum;
    }
}
