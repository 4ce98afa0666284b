using System.Numerics;
using AcDream.Core.Physics;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// Things that move: the player's body (<see cref="MovementOptions.Player"/>) on random 0.1–0.3 m moves in a 20 m patch of
/// open ground (the west half of <see cref="World.OpenGround"/>), with no mover registered (the baseline), with 1,000
/// creatures registered in the landblock 60 m and more away (none near a move), and with a crowd around the moves as
/// well (on average 10 creatures within 3 m of a start; each 0.48 m by 1.835 m); the last also asking what it touched.
/// </summary>
[MemoryDiagnoser]
public class MoverBenchmarks
{
    private const int Moves = 1024;
    private static readonly MovementOptions Player = MovementOptions.Player;
    private readonly Vector3[] _starts = new Vector3[Moves];
    private readonly Vector3[] _deltas = new Vector3[Moves];
    private readonly uint[] _cells = new uint[Moves];
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
        var crowd = new List<Vector2>();
        while (crowd.Count < 240)
        {
            var p = new Vector2(17f + (random.NextSingle() * 26f), 77f + (random.NextSingle() * 26f));
            if (crowd.TrueForAll(c => Vector2.Distance(c, p) >= 1f))
            {
                crowd.Add(p);
                _near.Movers.Add(5000u + (uint)crowd.Count, Human, new Vector3(p, centre.SampleZ(p.X, p.Y)), (World.Holtburg & 0xFFFF0000u) | World.OutdoorCell(p.X, p.Y), Quaternion.Identity, MoverState.Creature);
            }
        }

        _far.Movers.Commit();
        _near.Movers.Commit();
        double within = 0;
        for (int i = 0; i < Moves; i++)
        {
            Vector2 p;
            do
            {
                p = new Vector2(20f + (random.NextSingle() * 20f), 80f + (random.NextSingle() * 20f));
            }
            while (!crowd.TrueForAll(c => Vector2.Distance(c, p) >= 1f));
            _starts[i] = new Vector3(p, centre.SampleZ(p.X, p.Y));
            _cells[i] = (World.Holtburg & 0xFFFF0000u) | World.OutdoorCell(p.X, p.Y);
            _deltas[i] = World.RandomDelta(random, 0.1f, 0.3f);
            within += crowd.Count(c => Vector2.Distance(c, p) <= 3f);
        }

        int stopped = 0, touched = 0;
        for (int i = 0; i < Moves; i++)
        {
            ResolveResult r = _near.Resolve(_starts[i], _cells[i], _deltas[i], World.PlayerStepUp, in Player, 0u, _touched, out int count, out _);
            (stopped, touched) = (stopped + (r.Outcome is ResolveOutcome.Slid or ResolveOutcome.Wall ? 1 : 0), touched + (count > 0 ? 1 : 0));
            if (_far.Resolve(_starts[i], _cells[i], _deltas[i], World.PlayerStepUp, in Player) != _none.Resolve(_starts[i], _cells[i], _deltas[i], World.PlayerStepUp, in Player))
            {
                throw new InvalidOperationException($"move {i}: the far creatures changed an answer.");
            }
        }

        Console.WriteLine($"// crowd: {within / Moves:F1} creatures within 3 m of a start on average; {stopped}/{Moves} moves stopped or slid by one, {touched}/{Moves} touched one");
    }

    private float Run(PhysicsEngine engine)
    {
        float sum = 0f;
        for (int i = 0; i < Moves; i++)
        {
            ResolveResult r = engine.Resolve(_starts[i], _cells[i], _deltas[i], World.PlayerStepUp, in Player);
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
    public float Player_NoMovers() => Run(_none);

    /// <summary>The same moves with 1,000 creatures registered in the landblock, none near.</summary>
    [Benchmark(OperationsPerInvoke = Moves)]
    public float Player_ThousandFar() => Run(_far);

    /// <summary>The same moves among the crowd (and the 1,000 far).</summary>
    [Benchmark(OperationsPerInvoke = Moves)]
    public float Player_CrowdNear() => Run(_near);

    /// <summary>Among the crowd, also naming every mover touched (and the report).</summary>
    [Benchmark(OperationsPerInvoke = Moves)]
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
    public float Literal_NoMovers() => Literal(_none);

    /// <summary>The literal call with the 1,000 far creatures.</summary>
    [Benchmark(OperationsPerInvoke = Moves)]
    public float Literal_ThousandFar() => Literal(_far);
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
