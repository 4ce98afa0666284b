using System.Numerics;
using AcDream.Core.Physics;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// One Resolve per mover per frame: the literal four-argument call, each opt-in effect on alone, and
/// all of them (<see cref="MovementOptions.Player"/>, with the player's body since issue 10), all of
/// them but the body, and the body alone. Frame moves are 0.1..0.3 m (walking and running at 30 Hz),
/// shorter than a 0.48 m sweep; the <c>*_2m</c> pair moves 2 m (a remote entity's catch-up), where
/// the sweep takes 5 sub-steps. <see cref="BodyIndoorBenchmarks"/> has the body's own courses.
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
    private static readonly MovementOptions PlayerWithoutBody = MovementOptions.Player with { Body = null };
    private static readonly MovementOptions BodyOnlyOptions = new() { Body = MoverBody.Player };

    protected static ref readonly MovementOptions PlayerOptions => ref Player;

    protected static ref readonly MovementOptions NoBodyOptions => ref PlayerWithoutBody;

    protected static ref readonly MovementOptions BodyOptions => ref BodyOnlyOptions;

    protected static ref readonly MovementOptions NoOptions => ref None;

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

    /// <summary><see cref="MovementOptions.Player"/> without its body: every effect of issues 5 to 9.</summary>
    [Benchmark(OperationsPerInvoke = Moves)]
    public float AllEffectsNoBody() => Run(Deltas, in PlayerWithoutBody);

    /// <summary>The player's body alone (<see cref="MoverBody.Player"/>, no other effect).</summary>
    [Benchmark(OperationsPerInvoke = Moves)]
    public float BodyOnly() => Run(Deltas, in BodyOnlyOptions);

    /// <summary><see cref="MovementOptions.Player"/> with what each move met (the <see cref="MoveReport"/> overload).</summary>
    [Benchmark(OperationsPerInvoke = Moves)]
    public float AllEffectsReported()
    {
        float sum = 0f;
        for (int i = 0; i < Moves; i++)
        {
            sum += Sum(Engine.Resolve(Positions[i], CellIds[i], Deltas[i], World.PlayerStepUp, in Player, out MoveReport report)) + report.Floor.Id + report.Wall.Id;
        }

        return sum;
    }

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

    /// <summary>
    /// Throws unless the movers are on open ground: with no wall near, the body alone answers bit for
    /// bit as no effect, and <c>Player</c> as <c>Player</c> without a body except where a slope too
    /// steep to climb makes the body slide along its contour.
    /// </summary>
    protected void CheckOpenGround()
    {
        int contour = 0;
        for (int i = 0; i < Moves; i++)
        {
            foreach (Vector3[] deltas in new[] { Deltas, LongDeltas })
            {
                ResolveResult none = Engine.Resolve(Positions[i], CellIds[i], deltas[i], World.PlayerStepUp, in NoOptions);
                ResolveResult body = Engine.Resolve(Positions[i], CellIds[i], deltas[i], World.PlayerStepUp, in BodyOptions);
                ResolveResult noBody = Engine.Resolve(Positions[i], CellIds[i], deltas[i], World.PlayerStepUp, in NoBodyOptions);
                ResolveResult player = Engine.Resolve(Positions[i], CellIds[i], deltas[i], World.PlayerStepUp, in PlayerOptions);
                if (body != none)
                {
                    throw new InvalidOperationException($"Mover {i} at {Positions[i]} moving {deltas[i]} is not on open ground: with the body {body}, without {none}.");
                }

                if (player != noBody)
                {
                    contour += noBody.Outcome == ResolveOutcome.SlopeTooSteep && player.Outcome is ResolveOutcome.Slid or ResolveOutcome.SlopeTooSteep
                        ? 1
                        : throw new InvalidOperationException($"Mover {i} at {Positions[i]} moving {deltas[i]}: Player {player}, Player without a body {noBody}, and not a steep slope.");
                }
            }
        }

        Console.WriteLine($"// outdoor movers on open ground: the body alone answers as no effect for all {2 * Moves} moves (0.1–0.3 m and 2 m); Player differs from Player without a body on {contour} (steep slopes, slid along the contour); Player's outcomes: {Outcomes(PlayerOptions)}");
    }

    /// <summary>How many of the movers' 0.1–0.3 m moves end with each outcome under <paramref name="options"/> (for the setup's log).</summary>
    protected string Outcomes(in MovementOptions options)
    {
        var counts = new SortedDictionary<ResolveOutcome, int>();
        for (int i = 0; i < Moves; i++)
        {
            ResolveOutcome outcome = Engine.Resolve(Positions[i], CellIds[i], Deltas[i], World.PlayerStepUp, in options).Outcome;
            counts[outcome] = counts.GetValueOrDefault(outcome) + 1;
        }

        return string.Join(", ", counts.Select(kv => $"{kv.Key} {kv.Value}"));
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

        CheckOpenGround();
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
        Engine = World.IndoorEngine(surfaces);

        List<World.WallFace> walls = World.Walls(fixtures);
        int redrawn = 0;
        for (int i = 0; i < Moves; i++)
        {
            (Positions[i], CellIds[i]) = World.IndoorStart(random, fixtures, surfaces, walls, ref redrawn);
            Deltas[i] = World.RandomDelta(random, 0.1f, 0.3f);
            LongDeltas[i] = World.RandomDelta(random, 2f, 2f);
        }

        Console.WriteLine($"// indoor movers: {redrawn} starts redrawn because the player's body would overlap a wall; outcomes with the body: {Outcomes(BodyOptions)}; with Player: {Outcomes(PlayerOptions)}");
    }
}
