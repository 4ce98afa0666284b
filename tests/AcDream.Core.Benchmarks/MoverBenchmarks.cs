using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Testing;
using BenchmarkDotNet.Attributes;
using BenchmarkDotNet.Configs;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// Things that move: the player's body (<see cref="MovementOptions.Player"/>) on random 0.1–0.3 m moves in a 20 m patch of
/// open ground (the west half of <see cref="World.OpenGround"/>). Category "Clear": moves whose straight sweep, and path
/// without movers, clear every creature by 1 cm (double precision), with no mover registered (the baseline), with 1,000 creatures registered in the
/// landblock 60 m and more away (none near a move), and among a crowd as well (240 creatures 0.48 m × 1.835 m around the
/// patch, at least 1 m apart: 9 within 3 m of a start on average, as the setup prints), also naming what each touched; and the literal
/// call without and with the 1,000. Category "Touching": moves whose sweep meets a creature of the crowd, without movers
/// (the baseline) and among them: what colliding with one costs.
/// </summary>
[MemoryDiagnoser]
[GroupBenchmarksBy(BenchmarkLogicalGroupRule.ByCategory)]
public class MoverBenchmarks
{
    private const int Moves = 1024;
    private static readonly MovementOptions Player = MovementOptions.Player;
    private readonly Vector3[] _starts = new Vector3[Moves];
    private readonly Vector3[] _deltas = new Vector3[Moves];
    private readonly uint[] _cells = new uint[Moves];
    private readonly Vector3[] _touchingStarts = new Vector3[Moves];
    private readonly Vector3[] _touchingDeltas = new Vector3[Moves];
    private readonly uint[] _touchingCells = new uint[Moves];
    private readonly uint[] _touched = new uint[16];
    private PhysicsEngine _none = null!, _far = null!, _near = null!;

    /// <summary>The 1,000 creatures of a landblock away from the patch: x 100–190, y 4–188 (the east half).</summary>
    internal static void AddFar(PhysicsEngine engine, TerrainSurface centre, Random random, uint firstId)
    {
        for (uint i = 0; i < 1000; i++)
        {
            float x = 100f + (random.NextSingle() * 90f), y = 4f + (random.NextSingle() * 184f);
            engine.Movers.Add(firstId + i, Human, new Vector3(x, y, centre.SampleZ(x, y)), (World.Holtburg & 0xFFFF0000u) | World.OutdoorCell(x, y), Quaternion.Identity, MoverState.Creature);
        }
    }

    internal static MoverShape Human { get; } = MoverShape.Cylinder(0.48f, 1.835f);

    [GlobalSetup]
    public void Setup()
    {
        _none = World.OpenGround(new Random(5), out TerrainSurface centre);
        _far = World.OpenGround(new Random(5), out _);
        _near = World.OpenGround(new Random(5), out _);
        var random = new Random(11);
        AddFar(_far, centre, new Random(12), 1);
        AddFar(_near, centre, new Random(12), 1);

        // The crowd: 240 creatures in 26 m × 26 m around the patch, at least 1 m apart.
        var crowd = new List<Vector3>();
        while (crowd.Count < 240)
        {
            var p = new Vector2(17f + (random.NextSingle() * 26f), 77f + (random.NextSingle() * 26f));
            if (crowd.TrueForAll(c => Vector2.Distance(new Vector2(c.X, c.Y), p) >= 1f))
            {
                crowd.Add(new Vector3(p, centre.SampleZ(p.X, p.Y)));
                _near.Movers.Add(5000u + (uint)crowd.Count, Human, crowd[^1], (World.Holtburg & 0xFFFF0000u) | World.OutdoorCell(p.X, p.Y), Quaternion.Identity, MoverState.Creature);
            }
        }

        _far.Movers.Commit();
        _near.Movers.Commit();
        double within = 0;
        for (int clear = 0, touching = 0; clear < Moves || touching < Moves;)
        {
            var p = new Vector2(20f + (random.NextSingle() * 20f), 80f + (random.NextSingle() * 20f));
            var start = new Vector3(p, centre.SampleZ(p.X, p.Y));
            Vector3 delta = World.RandomDelta(random, 0.1f, 0.3f);
            uint cell = (World.Holtburg & 0xFFFF0000u) | World.OutdoorCell(p.X, p.Y);
            Vector3 end = _none.Resolve(start, cell, delta, World.PlayerStepUp, in Player).Position; // (a slope's contour slide leaves the line)
            double least = crowd.Min(c => Math.Min(MoverReference.SegmentTo(start, start + delta, c), MoverReference.SegmentTo(start, end, c)));
            if (least > 0.97 && clear < Moves)
            {
                (_starts[clear], _deltas[clear], _cells[clear]) = (start, delta, cell);
                within += crowd.Count(c => MoverReference.Apart(c, start) <= 3.0);
                clear++;
            }
            else if (least < 0.95 && crowd.Min(c => MoverReference.Apart(c, start)) > 0.97 && touching < Moves)
            {
                (_touchingStarts[touching], _touchingDeltas[touching], _touchingCells[touching]) = (start, delta, cell);
                touching++;
            }
        }

        int met = 0;
        for (int i = 0; i < Moves; i++)
        {
            if (_far.Resolve(_starts[i], _cells[i], _deltas[i], World.PlayerStepUp, in Player) != _none.Resolve(_starts[i], _cells[i], _deltas[i], World.PlayerStepUp, in Player)
                || _near.Resolve(_starts[i], _cells[i], _deltas[i], World.PlayerStepUp, in Player) != _none.Resolve(_starts[i], _cells[i], _deltas[i], World.PlayerStepUp, in Player))
            {
                throw new InvalidOperationException($"clear move {i}: a creature changed its answer.");
            }

            _near.Resolve(_touchingStarts[i], _touchingCells[i], _touchingDeltas[i], World.PlayerStepUp, in Player, 0u, _touched, out int count, out _);
            met += count > 0 ? 1 : 0;
        }

        Console.WriteLine($"// crowd: {within / Moves:F1} creatures within 3 m of a clear start on average; {met}/{Moves} touching moves named one touched");
    }

    private static float Run(PhysicsEngine engine, Vector3[] starts, Vector3[] deltas, uint[] cells)
    {
        float sum = 0f;
        for (int i = 0; i < Moves; i++)
        {
            ResolveResult r = engine.Resolve(starts[i], cells[i], deltas[i], World.PlayerStepUp, in Player);
            sum += r.Position.X + r.Position.Y + (r.IsOnGround ? 1f : 0f);
        }

        return sum;
    }

    private float Literal(PhysicsEngine engine)
    {
        float sum = 0f;
        for (int i = 0; i < Moves; i++)
        {
            ResolveResult r = engine.Resolve(_starts[i], _cells[i], _deltas[i], World.PlayerStepUp);
            sum += r.Position.X + r.Position.Y;
        }

        return sum;
    }

    /// <summary><see cref="MovementOptions.Player"/>, no mover registered: the baseline.</summary>
    [Benchmark(Baseline = true, OperationsPerInvoke = Moves)]
    [BenchmarkCategory("Clear")]
    public float Player_NoMovers() => Run(_none, _starts, _deltas, _cells);

    /// <summary>The same moves with 1,000 creatures registered in the landblock, none near.</summary>
    [Benchmark(OperationsPerInvoke = Moves)]
    [BenchmarkCategory("Clear")]
    public float Player_ThousandFar() => Run(_far, _starts, _deltas, _cells);

    /// <summary>The same moves among the crowd (and the 1,000 far): 9 creatures within 3 m on average, none touched.</summary>
    [Benchmark(OperationsPerInvoke = Moves)]
    [BenchmarkCategory("Clear")]
    public float Player_CrowdNear() => Run(_near, _starts, _deltas, _cells);

    /// <summary>Among the crowd, also naming every mover touched (and the report).</summary>
    [Benchmark(OperationsPerInvoke = Moves)]
    [BenchmarkCategory("Clear")]
    public float Player_CrowdNear_Touches()
    {
        float sum = 0f;
        for (int i = 0; i < Moves; i++)
        {
            ResolveResult r = _near.Resolve(_starts[i], _cells[i], _deltas[i], World.PlayerStepUp, in Player, 0u, _touched, out int count, out _);
            sum += r.Position.X + r.Position.Y + count;
        }

        return sum;
    }

    /// <summary>The literal call, no mover registered.</summary>
    [Benchmark(OperationsPerInvoke = Moves)]
    [BenchmarkCategory("Clear")]
    public float Literal_NoMovers() => Literal(_none);

    /// <summary>The literal call with the 1,000 far creatures.</summary>
    [Benchmark(OperationsPerInvoke = Moves)]
    [BenchmarkCategory("Clear")]
    public float Literal_ThousandFar() => Literal(_far);

    /// <summary>Moves whose sweep meets a creature of the crowd, no mover registered: the baseline of its category.</summary>
    [Benchmark(Baseline = true, OperationsPerInvoke = Moves)]
    [BenchmarkCategory("Touching")]
    public float Touching_NoMovers() => Run(_none, _touchingStarts, _touchingDeltas, _touchingCells);

    /// <summary>The same moves among the crowd: each meets a creature (slides round it or stops).</summary>
    [Benchmark(OperationsPerInvoke = Moves)]
    [BenchmarkCategory("Touching")]
    public float Touching_Crowd() => Run(_near, _touchingStarts, _touchingDeltas, _touchingCells);
}

/// <summary>
/// The writer's frame: moving 1,000 registered creatures (all of them, each by up to 0.3 m and a turn) and committing,
/// against 1,000 literal <c>Resolve</c> calls of the same run (the baseline; random 0.1–0.3 m moves on the open ground).
/// </summary>
[MemoryDiagnoser]
public class MoverUpdateBenchmarks
{
    private const int Count = 1000;
    private readonly Vector3[][] _at = [new Vector3[Count], new Vector3[Count]];
    private readonly uint[] _creatureCells = new uint[Count];
    private readonly Vector3[] _starts = new Vector3[Count];
    private readonly Vector3[] _deltas = new Vector3[Count];
    private readonly uint[] _cells = new uint[Count];
    private PhysicsEngine _engine = null!;
    private int _frame;

    [GlobalSetup]
    public void Setup()
    {
        _engine = World.OpenGround(new Random(5), out TerrainSurface centre);
        MoverBenchmarks.AddFar(_engine, centre, new Random(12), 1);
        var random = new Random(13);
        for (int i = 0; i < Count; i++)
        {
            float x = 100f + (random.NextSingle() * 90f), y = 4f + (random.NextSingle() * 184f);
            _at[0][i] = new Vector3(x, y, centre.SampleZ(x, y));
            _at[1][i] = _at[0][i] + new Vector3(World.RandomDelta(random, 0.1f, 0.3f).AsVector2(), 0f);
            _creatureCells[i] = (World.Holtburg & 0xFFFF0000u) | World.OutdoorCell(x, y);
            float sx = 4f + (random.NextSingle() * 86f), sy = 4f + (random.NextSingle() * 184f);
            _starts[i] = new Vector3(sx, sy, centre.SampleZ(sx, sy));
            _cells[i] = (World.Holtburg & 0xFFFF0000u) | World.OutdoorCell(sx, sy);
            _deltas[i] = World.RandomDelta(random, 0.1f, 0.3f);
        }

        _engine.Movers.Commit();
    }

    /// <summary>1,000 literal calls: the baseline.</summary>
    [Benchmark(Baseline = true)]
    public float Literal_ThousandCalls()
    {
        float sum = 0f;
        for (int i = 0; i < Count; i++)
        {
            sum += _engine.Resolve(_starts[i], _cells[i], _deltas[i], World.PlayerStepUp).Position.X;
        }

        return sum;
    }

    /// <summary>One frame of the writer: every creature moved and turned, then committed.</summary>
    [Benchmark]
    public int Update_ThousandCreatures()
    {
        Vector3[] at = _at[++_frame & 1];
        Quaternion turn = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, _frame * 0.01f);
        for (int i = 0; i < Count; i++)
        {
            _engine.Movers.Move((uint)(i + 1), at[i], _creatureCells[i], turn);
        }

        _engine.Movers.Commit();
        return _frame;
    }
}
