using System.Numerics;
using AcDream.Core.Physics;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// One Resolve per mover per frame: the literal four-argument call, each opt-in effect on alone, and
/// all of them (<see cref="MovementOptions.Player"/>). Frame moves are 0.1..0.3 m (walking and
/// running at 30 Hz), shorter than a 0.48 m sweep; the <c>*_2m</c> pair moves 2 m (a remote
/// entity's catch-up), where the sweep takes 5 sub-steps.
/// </summary>
[MemoryDiagnoser]
public abstract class ResolveBenchmarks
{
    protected const int Moves = 1024;

    private static readonly MovementOptions None = default;
    private static readonly MovementOptions StepDownOnly = new() { StepDownHeight = 1.5f };
    private static readonly MovementOptions WalkableOnly = new() { WalkableSlope = true };
    private static readonly MovementOptions SweptOnly = new() { SweepStepLength = 0.48f };
    private static readonly MovementOptions DoorsOnlyOnly = new() { DoorsOnly = true };
    private static readonly MovementOptions Player = MovementOptions.Player;

    protected PhysicsEngine Engine { get; set; } = null!;

    protected Vector3[] Positions { get; } = new Vector3[Moves];

    protected uint[] CellIds { get; } = new uint[Moves];

    protected Vector3[] Deltas { get; } = new Vector3[Moves];

    protected Vector3[] LongDeltas { get; } = new Vector3[Moves];

    [Benchmark(Baseline = true, OperationsPerInvoke = Moves)]
    public float Literal()
    {
        float sum = 0f;
        for (int i = 0; i < Moves; i++)
        {
            sum += Sum(Engine.Resolve(Positions[i], CellIds[i], Deltas[i], World.PlayerStepUp));
        }

        return sum;
    }

    [Benchmark(OperationsPerInvoke = Moves)]
    public float NoEffects() => Run(Deltas, in None);

    [Benchmark(OperationsPerInvoke = Moves)]
    public float StepDown() => Run(Deltas, in StepDownOnly);

    [Benchmark(OperationsPerInvoke = Moves)]
    public float WalkableSlope() => Run(Deltas, in WalkableOnly);

    [Benchmark(OperationsPerInvoke = Moves)]
    public float Swept() => Run(Deltas, in SweptOnly);

    [Benchmark(OperationsPerInvoke = Moves)]
    public float DoorsOnly() => Run(Deltas, in DoorsOnlyOnly);

    [Benchmark(OperationsPerInvoke = Moves)]
    public float AllEffects() => Run(Deltas, in Player);

    [Benchmark(OperationsPerInvoke = Moves)]
    public float Literal_2m() => Run(LongDeltas, in None);

    [Benchmark(OperationsPerInvoke = Moves)]
    public float Swept_2m() => Run(LongDeltas, in SweptOnly);

    private float Run(Vector3[] deltas, in MovementOptions options)
    {
        float sum = 0f;
        for (int i = 0; i < Moves; i++)
        {
            sum += Sum(Engine.Resolve(Positions[i], CellIds[i], deltas[i], World.PlayerStepUp, in options));
        }

        return sum;
    }

    private static float Sum(ResolveResult r) => r.Position.X + r.Position.Z + r.CellId + (r.IsOnGround ? 1f : 0f);
}

/// <summary>
/// Outdoor movers in the west half of Holtburg on rolling triangle terrain, with 0, 8 or 64
/// buildings per landblock (all in the east half, so never under a mover) and 1 or 9 landblocks.
/// </summary>
public class ResolveOutdoorBenchmarks : ResolveBenchmarks
{
    [Params(0, 8, 64)]
    public int Cells { get; set; }

    [Params(1, 9)]
    public int Landblocks { get; set; }

    [GlobalSetup]
    public void Setup()
    {
        var random = new Random(5);
        float[] table = World.NonLinearTable();
        Engine = new PhysicsEngine(World.Holtburg);
        TerrainSurface centre = null!;
        foreach (uint id in World.Landblocks(Landblocks))
        {
            var terrain = new TerrainSurface(World.RollingHeights(random, 60, 6), table, id);
            Engine.AddLandblock(id, terrain, World.Buildings(id, terrain, Cells));
            centre ??= terrain;
        }

        for (int i = 0; i < Moves; i++)
        {
            float x = 4f + (random.NextSingle() * 86f), y = 4f + (random.NextSingle() * 184f);
            Positions[i] = new Vector3(x, y, centre.SampleZ(x, y));
            CellIds[i] = (World.Holtburg & 0xFFFF0000u) | World.OutdoorCell(x, y);
            Deltas[i] = World.RandomDelta(random, 0.1f, 0.3f);
            LongDeltas[i] = World.RandomDelta(random, 2f, 2f);
        }
    }
}

/// <summary>Indoor movers on the floors of the 22 real Holtburg cells (two cottages, their cellars and upper floors).</summary>
public class ResolveIndoorBenchmarks : ResolveBenchmarks
{
    [GlobalSetup]
    public void Setup()
    {
        var random = new Random(5);
        var fixtures = World.HoltburgFixtures();
        List<CellSurface> surfaces = World.Surfaces(fixtures);
        Engine = new PhysicsEngine(World.Holtburg);
        Engine.AddLandblock(World.Holtburg, new TerrainSurface(new byte[81], World.ConstantTable(World.HoltburgGroundZ), World.Holtburg), surfaces);
        Engine.AddLandblock(0xA9B3FFFFu, new TerrainSurface(new byte[81], World.ConstantTable(World.HoltburgGroundZ), 0xA9B3FFFFu), []);

        for (int i = 0; i < Moves;)
        {
            int c = random.Next(fixtures.Count);
            (Vector2 min, Vector2 max) = World.Bounds(fixtures[c]);
            float x = min.X + (random.NextSingle() * (max.X - min.X)), y = min.Y + (random.NextSingle() * (max.Y - min.Y));
            if (surfaces[c].SampleFloorZ(x, y) is not float z)
            {
                continue; // no floor there (a wall's footprint, a shaft): draw again
            }

            Positions[i] = new Vector3(x, y, z);
            CellIds[i] = surfaces[c].CellId;
            Deltas[i] = World.RandomDelta(random, 0.1f, 0.3f);
            LongDeltas[i] = World.RandomDelta(random, 2f, 2f);
            i++;
        }
    }
}
