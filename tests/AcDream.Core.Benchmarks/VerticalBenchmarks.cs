using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.Core.Physics;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// The body in three dimensions (issue 19): <see cref="MovementOptions.Player"/> (vertical motion, footing, edge slide)
/// on random 0.1–0.3 m moves, grounded (the baseline: feet on the ground, no Z in the delta) and in the air with the
/// same horizontal moves (feet 0.5 m over the ground, falling 5 cm or rising 5 cm; the real rooms are 2.8 m high); the grounded moves without edge
/// slide, and without any of the three effects (the body across the ground alone); and the literal call.
/// </summary>
[MemoryDiagnoser]
public abstract class VerticalBenchmarks
{
    protected const int Moves = 1024;

    private static readonly MovementOptions Player = MovementOptions.Player;
    private static readonly MovementOptions NoEdgeSlide = MovementOptions.Player with { EdgeSlide = false };
    private static readonly MovementOptions Flat = MovementOptions.Player with { Vertical = false, Footing = false, EdgeSlide = false };

    protected PhysicsEngine Engine { get; set; } = null!;

    protected Vector3[] Grounded { get; } = new Vector3[Moves];

    protected Vector3[] InTheAir { get; } = new Vector3[Moves];

    protected uint[] Cells { get; } = new uint[Moves];

    protected Vector3[] Across { get; } = new Vector3[Moves];

    protected Vector3[] Falling { get; } = new Vector3[Moves];

    protected Vector3[] Rising { get; } = new Vector3[Moves];

    /// <summary>Fills the air starts and the deltas from the grounded starts and <see cref="Across"/>; checks the kinds of answer.</summary>
    protected void Finish(string where)
    {
        for (int i = 0; i < Moves; i++)
        {
            InTheAir[i] = Grounded[i] + new Vector3(0f, 0f, 0.5f);
            Falling[i] = Across[i] with { Z = -0.05f };
            Rising[i] = Across[i] with { Z = 0.05f };
        }

        int grounded = Count(Grounded, Across, r => r.IsOnGround), falling = Count(InTheAir, Falling, r => !r.IsOnGround), rising = Count(InTheAir, Rising, r => !r.IsOnGround);
        Console.WriteLine($"// {where}: grounded answers {grounded}/{Moves}; in the air after a fall {falling}/{Moves}, after a rise {rising}/{Moves}");
        if (grounded < Moves * 9 / 10 || falling < Moves * 9 / 10 || rising < Moves * 9 / 10)
        {
            throw new InvalidOperationException($"{where}: the moves are not the kinds the rows name.");
        }
    }

    private int Count(Vector3[] starts, Vector3[] deltas, Func<ResolveResult, bool> kind)
    {
        int n = 0;
        for (int i = 0; i < Moves; i++)
        {
            n += kind(Engine.Resolve(starts[i], Cells[i], deltas[i], World.PlayerStepUp, in Player)) ? 1 : 0;
        }

        return n;
    }

    private float Run(Vector3[] starts, Vector3[] deltas, in MovementOptions options)
    {
        float sum = 0f;
        for (int i = 0; i < Moves; i++)
        {
            ResolveResult r = Engine.Resolve(starts[i], Cells[i], deltas[i], World.PlayerStepUp, in options);
            sum += r.Position.X + r.Position.Z + (r.IsOnGround ? 1f : 0f);
        }

        return sum;
    }

    /// <summary><see cref="MovementOptions.Player"/>, grounded: the baseline.</summary>
    [Benchmark(Baseline = true, OperationsPerInvoke = Moves)]
    public float Player_Grounded() => Run(Grounded, Across, in Player);

    /// <summary>The same horizontal moves 0.5 m over the ground, falling 5 cm.</summary>
    [Benchmark(OperationsPerInvoke = Moves)]
    public float Player_Falling() => Run(InTheAir, Falling, in Player);

    /// <summary>The same horizontal moves 0.5 m over the ground, rising 5 cm.</summary>
    [Benchmark(OperationsPerInvoke = Moves)]
    public float Player_Rising() => Run(InTheAir, Rising, in Player);

    /// <summary>Grounded, without edge slide.</summary>
    [Benchmark(OperationsPerInvoke = Moves)]
    public float Player_NoEdgeSlide() => Run(Grounded, Across, in NoEdgeSlide);

    /// <summary>Grounded, without vertical motion, footing and edge slide (the body across the ground alone).</summary>
    [Benchmark(OperationsPerInvoke = Moves)]
    public float Player_Flat() => Run(Grounded, Across, in Flat);

    /// <summary>The literal call on the grounded moves.</summary>
    [Benchmark(OperationsPerInvoke = Moves)]
    public float Literal()
    {
        float sum = 0f;
        for (int i = 0; i < Moves; i++)
        {
            ResolveResult r = Engine.Resolve(Grounded[i], Cells[i], Across[i], World.PlayerStepUp);
            sum += r.Position.X + r.Position.Z + (r.IsOnGround ? 1f : 0f);
        }

        return sum;
    }
}

/// <summary>Open ground: 64 buildings in each of 9 landblocks, none near the movers (as <see cref="BodyOutdoorBenchmarks"/>).</summary>
public class VerticalOutdoorBenchmarks : VerticalBenchmarks
{
    [GlobalSetup]
    public void Setup()
    {
        var random = new Random(5);
        Engine = World.OpenGround(random, out TerrainSurface centre);

        for (int i = 0; i < Moves; i++)
        {
            float x = 4f + (random.NextSingle() * 86f), y = 4f + (random.NextSingle() * 184f);
            Grounded[i] = new Vector3(x, y, centre.SampleZ(x, y));
            Cells[i] = (World.Holtburg & 0xFFFF0000u) | World.OutdoorCell(x, y);
            Across[i] = World.RandomDelta(random, 0.1f, 0.3f);
        }

        Finish("outdoors, open ground");
    }
}

/// <summary>Indoors on the 22 real Holtburg cells, from floor points where the body stands clear of every wall (as <see cref="BodyIndoorBenchmarks"/>).</summary>
public class VerticalIndoorBenchmarks : VerticalBenchmarks
{
    [GlobalSetup]
    public void Setup()
    {
        var random = new Random(5);
        List<CellFixtureReader.FixtureCell> fixtures = World.HoltburgFixtures();
        List<CellSurface> surfaces = World.Surfaces(fixtures);
        List<World.WallFace> walls = World.Walls(fixtures);
        Engine = World.IndoorEngine(surfaces);
        int redrawn = 0;
        for (int i = 0; i < Moves; i++)
        {
            (Grounded[i], Cells[i]) = World.IndoorStart(random, fixtures, surfaces, walls, ref redrawn);
            Across[i] = World.RandomDelta(random, 0.1f, 0.3f);
        }

        Finish("indoors, the real cells");
    }
}
