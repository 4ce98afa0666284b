using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.Core.Physics;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// The body (issue 10) on its own courses, each row against a baseline of the same run: 1,024 movers
/// per invocation, the player's body (<see cref="MoverBody.Player"/>: radius 0.48 m, 1.835 m tall).
/// "Body" rows use the body alone (<c>new MovementOptions { Body = MoverBody.Player }</c>: no
/// sub-steps), "Player" rows <see cref="MovementOptions.Player"/> (the body and every other effect).
/// </summary>
[MemoryDiagnoser]
public abstract class BodyBenchmarks
{
    protected const int Moves = 1024;

    private static readonly MovementOptions None = default;
    private static readonly MovementOptions BodyAlone = new() { Body = MoverBody.Player };
    private static readonly MovementOptions Player = MovementOptions.Player;
    private static readonly MovementOptions PlayerWithoutBody = MovementOptions.Player with { Body = null };

    protected PhysicsEngine Engine { get; set; } = null!;

    /// <summary>Starts of the 0.1–0.3 m moves and of the 0.2 m / 2 m pair.</summary>
    protected Vector3[] Positions { get; } = new Vector3[Moves];

    protected uint[] CellIds { get; } = new uint[Moves];

    /// <summary>0.1–0.3 m moves in random directions.</summary>
    protected Vector3[] Deltas { get; } = new Vector3[Moves];

    /// <summary>Exactly 0.2 m, in random directions.</summary>
    protected Vector3[] Short { get; } = new Vector3[Moves];

    /// <summary>Exactly 2 m, in the directions of <see cref="Short"/>.</summary>
    protected Vector3[] Long { get; } = new Vector3[Moves];

    protected static ref readonly MovementOptions BodyOptions => ref BodyAlone;

    protected static ref readonly MovementOptions NoOptions => ref None;

    protected static ref readonly MovementOptions PlayerOptions => ref Player;

    protected static ref readonly MovementOptions PlayerWithoutBodyOptions => ref PlayerWithoutBody;

    protected float Literal(Vector3[] positions, uint[] cells, Vector3[] deltas)
    {
        float sum = 0f;
        for (int i = 0; i < Moves; i++)
        {
            sum += Sum(Engine.Resolve(positions[i], cells[i], deltas[i], World.PlayerStepUp));
        }

        return sum;
    }

    protected float Run(Vector3[] positions, uint[] cells, Vector3[] deltas, in MovementOptions options)
    {
        float sum = 0f;
        for (int i = 0; i < Moves; i++)
        {
            sum += Sum(Engine.Resolve(positions[i], cells[i], deltas[i], World.PlayerStepUp, in options));
        }

        return sum;
    }

    protected float RunBody(Vector3[] deltas) => Run(Positions, CellIds, deltas, in BodyAlone);

    protected float RunPlayer(Vector3[] deltas) => Run(Positions, CellIds, deltas, in Player);

    protected float RunPlayerWithoutBody(Vector3[] deltas) => Run(Positions, CellIds, deltas, in PlayerWithoutBody);

    /// <summary>How many of <paramref name="deltas"/> end with each outcome (for the setup's log).</summary>
    protected string Outcomes(Vector3[] positions, uint[] cells, Vector3[] deltas, in MovementOptions options)
    {
        var counts = new SortedDictionary<ResolveOutcome, int>();
        for (int i = 0; i < Moves; i++)
        {
            ResolveOutcome outcome = Engine.Resolve(positions[i], cells[i], deltas[i], World.PlayerStepUp, in options).Outcome;
            counts[outcome] = counts.GetValueOrDefault(outcome) + 1;
        }

        return string.Join(", ", counts.Select(kv => $"{kv.Key} {kv.Value}"));
    }

    protected void RandomMoves(Random random, int i)
    {
        Deltas[i] = World.RandomDelta(random, 0.1f, 0.3f);
        Short[i] = World.RandomDelta(random, 0.2f, 0.2f);
        Long[i] = Short[i] * 10f;
    }

    protected static float Sum(ResolveResult r) => r.Position.X + r.Position.Z + r.CellId + (r.IsOnGround ? 1f : 0f);
}

/// <summary>
/// Indoors, on the 22 real Holtburg cells: random 0.1–0.3 m moves from floor points where the body
/// stands clear of every wall (baseline: the literal call on them), a course of moves that slide along
/// a wall, and a 0.2 m vs 2 m move from the same starts in the same directions (all of them, and those
/// whose 2 m move meets no wall).
/// </summary>
public class BodyIndoorBenchmarks : BodyBenchmarks
{
    private readonly Vector3[] _slideStarts = new Vector3[Moves];
    private readonly uint[] _slideCells = new uint[Moves];
    private readonly Vector3[] _slideDeltas = new Vector3[Moves];
    private readonly Vector3[] _freeStarts = new Vector3[Moves];
    private readonly uint[] _freeCells = new uint[Moves];
    private readonly Vector3[] _freeShort = new Vector3[Moves];
    private readonly Vector3[] _freeLong = new Vector3[Moves];

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
            (Positions[i], CellIds[i]) = World.IndoorStart(random, fixtures, surfaces, walls, ref redrawn);
            RandomMoves(random, i);
        }

        // The movers whose 2 m move with the body meets no wall (outcome Moved), cycled to fill the
        // arrays: the same pair of lengths without contacts, so the rows show what length alone costs.
        var free = Enumerable.Range(0, Moves)
            .Where(i => Engine.Resolve(Positions[i], CellIds[i], Long[i], World.PlayerStepUp, in BodyOptions).Outcome == ResolveOutcome.Moved)
            .ToList();
        if (free.Count < 100)
        {
            throw new InvalidOperationException($"Only {free.Count} of {Moves} indoor 2 m moves meet no wall.");
        }

        for (int i = 0; i < Moves; i++)
        {
            int k = free[i % free.Count];
            (_freeStarts[i], _freeCells[i], _freeShort[i], _freeLong[i]) = (Positions[k], CellIds[k], Short[k], Long[k]);
        }

        string report = SlideCourse.Build(random, Engine, fixtures, surfaces, walls, _slideStarts, _slideCells, _slideDeltas);
        Console.WriteLine($"// indoor random movers: {redrawn} starts redrawn (the body would overlap a wall); 0.1–0.3 m with the body: {Outcomes(Positions, CellIds, Deltas, in BodyOptions)}");
        Console.WriteLine($"// 0.2 m with the body: {Outcomes(Positions, CellIds, Short, in BodyOptions)}; 2 m: {Outcomes(Positions, CellIds, Long, in BodyOptions)}");
        Console.WriteLine($"// slide course: {report}; literal on it: {Outcomes(_slideStarts, _slideCells, _slideDeltas, in NoOptions)}");
        Console.WriteLine($"// 2 m moves meeting no wall: {free.Count} distinct of {Moves}; their 0.2 m moves: {Outcomes(_freeStarts, _freeCells, _freeShort, in BodyOptions)}");
    }

    /// <summary>
    /// The literal four-argument call on the random 0.1–0.3 m moves: the baseline. Written as
    /// <see cref="ResolveBenchmarks.Literal"/> is (the same movers: same seed and draws), since the
    /// shape of the loop moves the literal row by 10–30 % here (the JIT's code for it).
    /// </summary>
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
    public float AllEffectsNoBody() => RunPlayerWithoutBody(Deltas);

    [Benchmark(OperationsPerInvoke = Moves)]
    public float Body() => RunBody(Deltas);

    [Benchmark(OperationsPerInvoke = Moves)]
    public float Player() => RunPlayer(Deltas);

    /// <summary>The literal call on the slide course (a point: it walks on towards the wall).</summary>
    [Benchmark(OperationsPerInvoke = Moves)]
    public float Slide_Literal() => Literal(_slideStarts, _slideCells, _slideDeltas);

    [Benchmark(OperationsPerInvoke = Moves)]
    public float Slide_Body() => Run(_slideStarts, _slideCells, _slideDeltas, in BodyOptions);

    [Benchmark(OperationsPerInvoke = Moves)]
    public float Slide_Player() => Run(_slideStarts, _slideCells, _slideDeltas, in PlayerOptions);

    [Benchmark(OperationsPerInvoke = Moves)]
    public float Body_0_2m() => RunBody(Short);

    [Benchmark(OperationsPerInvoke = Moves)]
    public float Body_2m() => RunBody(Long);

    /// <summary>0.2 m with the body from the starts whose 2 m move meets no wall.</summary>
    [Benchmark(OperationsPerInvoke = Moves)]
    public float Body_0_2m_NoContact() => Run(_freeStarts, _freeCells, _freeShort, in BodyOptions);

    /// <summary>2 m with the body meeting no wall.</summary>
    [Benchmark(OperationsPerInvoke = Moves)]
    public float Body_2m_NoContact() => Run(_freeStarts, _freeCells, _freeLong, in BodyOptions);

    /// <summary>The literal call's 2 m move from the same starts (a point: no walls, only floors and portals).</summary>
    [Benchmark(OperationsPerInvoke = Moves)]
    public float Literal_2m_NoContact() => Literal(_freeStarts, _freeCells, _freeLong);
}

/// <summary>
/// Outdoors on open ground: the movers of <see cref="ResolveOutdoorBenchmarks"/> with 64 buildings
/// per landblock and 9 landblocks (the buildings all in the east half, so no wall near a mover),
/// against <c>Player</c> without a body; and a 0.2 m vs 2 m move with the body alone.
/// </summary>
public class BodyOutdoorBenchmarks : BodyBenchmarks
{
    [GlobalSetup]
    public void Setup()
    {
        var random = new Random(5);
        Engine = World.OpenGround(random, out TerrainSurface centre);

        for (int i = 0; i < Moves; i++)
        {
            float x = 4f + (random.NextSingle() * 86f), y = 4f + (random.NextSingle() * 184f);
            Positions[i] = new Vector3(x, y, centre.SampleZ(x, y));
            CellIds[i] = (World.Holtburg & 0xFFFF0000u) | World.OutdoorCell(x, y);
            RandomMoves(random, i);
        }

        // Open ground: with no wall near, the body alone must answer as no effect, bit for bit.
        foreach (Vector3[] deltas in new[] { Deltas, Short, Long })
        {
            for (int i = 0; i < Moves; i++)
            {
                ResolveResult point = Engine.Resolve(Positions[i], CellIds[i], deltas[i], World.PlayerStepUp, in NoOptions);
                ResolveResult body = Engine.Resolve(Positions[i], CellIds[i], deltas[i], World.PlayerStepUp, in BodyOptions);
                if (body != point)
                {
                    throw new InvalidOperationException($"Mover {i} at {Positions[i]} moving {deltas[i]} is not on open ground: with the body {body}, without {point}.");
                }
            }
        }

        Console.WriteLine($"// outdoor movers: the body alone answers as no effect on all {3 * Moves} moves; Player's outcomes (0.1–0.3 m): {Outcomes(Positions, CellIds, Deltas, in PlayerOptions)}");

        // Moves no slope refuses: Player's body never slides along a contour on them, so the two
        // rows differ by the body's own cost (its open-ground check) alone.
        for (int n = 0; n < Moves;)
        {
            float x = 4f + (random.NextSingle() * 86f), y = 4f + (random.NextSingle() * 184f);
            var at = new Vector3(x, y, centre.SampleZ(x, y));
            uint cell = (World.Holtburg & 0xFFFF0000u) | World.OutdoorCell(x, y);
            Vector3 delta = World.RandomDelta(random, 0.1f, 0.3f);
            if (Engine.Resolve(at, cell, delta, World.PlayerStepUp, in PlayerWithoutBodyOptions).Outcome != ResolveOutcome.SlopeTooSteep)
            {
                (UnrefusedPositions[n], UnrefusedCells[n], UnrefusedDeltas[n]) = (at, cell, delta);
                n++;
            }
        }

        Console.WriteLine($"// outdoor movers no slope refuses: Player's outcomes {Outcomes(UnrefusedPositions, UnrefusedCells, UnrefusedDeltas, in PlayerOptions)}");
    }

    private Vector3[] UnrefusedPositions { get; } = new Vector3[Moves];

    private uint[] UnrefusedCells { get; } = new uint[Moves];

    private Vector3[] UnrefusedDeltas { get; } = new Vector3[Moves];

    /// <summary><see cref="MovementOptions.Player"/> without its body on the 0.1–0.3 m moves: the baseline.</summary>
    [Benchmark(Baseline = true, OperationsPerInvoke = Moves)]
    public float AllEffectsNoBody() => RunPlayerWithoutBody(Deltas);

    [Benchmark(OperationsPerInvoke = Moves)]
    public float Player() => RunPlayer(Deltas);

    [Benchmark(OperationsPerInvoke = Moves)]
    public float Body() => RunBody(Deltas);

    [Benchmark(OperationsPerInvoke = Moves)]
    public float Literal() => Literal(Positions, CellIds, Deltas);

    [Benchmark(OperationsPerInvoke = Moves)]
    public float Body_0_2m() => RunBody(Short);

    [Benchmark(OperationsPerInvoke = Moves)]
    public float Body_2m() => RunBody(Long);

    /// <summary><see cref="MovementOptions.Player"/> without its body, on moves no slope refuses.</summary>
    [Benchmark(OperationsPerInvoke = Moves)]
    public float AllEffectsNoBody_Unrefused() => Run(UnrefusedPositions, UnrefusedCells, UnrefusedDeltas, in PlayerWithoutBodyOptions);

    /// <summary><see cref="MovementOptions.Player"/> on the same moves: the body adds only its open-ground check.</summary>
    [Benchmark(OperationsPerInvoke = Moves)]
    public float Player_Unrefused() => Run(UnrefusedPositions, UnrefusedCells, UnrefusedDeltas, in PlayerOptions);
}

/// <summary>
/// Movers placed near a real wall and moving diagonally into it, so the body touches it part way and
/// slides along it for the rest of the move. Placed from the fixtures' own geometry (not the
/// engine's walls) and each checked against it: the answer must be a slide along that wall, ending
/// at the body's radius from its plane and as far along it as the move's component along it.
/// </summary>
internal static class SlideCourse
{
    /// <summary>A wall must be at least this long for a start away from its ends (metres).</summary>
    private const float MinWallLength = 1.6f;

    /// <summary>Tolerance of the geometric check of an accepted slide (metres).</summary>
    private const float Tolerance = 0.001f;

    /// <summary>Fills the arrays; returns what it drew and rejected. Throws when the course cannot be filled.</summary>
    public static string Build(
        Random random, PhysicsEngine engine, List<CellFixtureReader.FixtureCell> fixtures, List<CellSurface> surfaces, List<World.WallFace> walls,
        Vector3[] starts, uint[] cells, Vector3[] deltas)
    {
        MoverBody body = MoverBody.Player;
        var options = new MovementOptions { Body = body };
        var surfaceOf = new Dictionary<uint, CellSurface>();
        foreach (CellSurface s in surfaces)
        {
            surfaceOf[s.CellId] = s;
        }

        List<World.WallFace> candidates = walls.Where(w => w.IsVertical && Extent(w).Length >= MinWallLength).ToList();
        int tried = 0, noFloor = 0, notClear = 0, otherOutcome = 0, otherWall = 0, mismatch = 0;
        string? firstMismatch = null;
        var outcomes = new SortedDictionary<ResolveOutcome, int>();
        int n = 0;
        while (n < starts.Length)
        {
            if (++tried > 200 * starts.Length)
            {
                throw new InvalidOperationException($"Slide course: only {n} of {starts.Length} slides in {tried} tries (no floor {noFloor}, not clear {notClear}, other outcome {otherOutcome}, another wall {otherWall}, geometry mismatch {mismatch}).");
            }

            World.WallFace wall = candidates[random.Next(candidates.Count)];
            (float length, Vector2 a, Vector2 along, Vector2 normal) = Extent(wall);
            Vector2 side = random.Next(2) == 0 ? normal : -normal; // the room may be on either side of the winding
            float s = body.Radius + 0.2f + (random.NextSingle() * (length - (2 * body.Radius) - 0.4f));
            float move = 0.1f + (random.NextSingle() * 0.2f);
            float angle = (30f + (random.NextSingle() * 40f)) * MathF.PI / 180f; // from the wall's normal
            float into = move * MathF.Cos(angle), across = move * MathF.Sin(angle) * (random.Next(2) == 0 ? 1f : -1f);
            float gap = 0.005f + (random.NextSingle() * ((0.6f * into) - 0.005f)); // touches in the first 60 % of the move
            Vector2 start = a + (along * s) + (side * (body.Radius + gap));
            if (!surfaceOf.TryGetValue(wall.CellId, out CellSurface? surface) || surface.SampleFloorZ(start.X, start.Y, wall.ZMin + 0.1f) is not float z
                || wall.ZMin > z + World.PlayerStepUp || wall.ZMax < z + body.Height)
            {
                noFloor++;
                continue; // nothing to stand on beside the wall on this side, or the wall does not span the body
            }

            if (World.Clearance(walls, start, z + World.PlayerStepUp, z + body.Height) < body.Radius)
            {
                notClear++;
                continue;
            }

            var position = new Vector3(start, z);
            var delta = new Vector3((-side * into) + (along * across), 0f);
            ResolveResult r = engine.Resolve(position, wall.CellId, delta, World.PlayerStepUp, in options);
            outcomes[r.Outcome] = outcomes.GetValueOrDefault(r.Outcome) + 1;
            if (r.Outcome != ResolveOutcome.Slid)
            {
                otherOutcome++;
                continue;
            }

            var end = new Vector2(r.Position.X, r.Position.Y);
            float offWall = Vector2.Dot(end - a, side);
            float travelled = Vector2.Dot(end - start, along);
            if (Vector2.Dot(new Vector2(r.SurfaceNormal.X, r.SurfaceNormal.Y), side) < 0.99f)
            {
                otherWall++;
                continue; // slid along another wall (a corner, a jamb): not this course
            }

            if (MathF.Abs(offWall - body.Radius) > Tolerance || MathF.Abs(travelled - across) > Tolerance)
            {
                mismatch++;
                firstMismatch ??= $"start {position} in {wall.CellId:X8} moving {delta}: {r}; {offWall:0.#####} m off the wall (radius {body.Radius}), {travelled:0.#####} m along it (the move's component {across:0.#####})";
                continue;
            }

            (starts[n], cells[n], deltas[n]) = (position, wall.CellId, delta);
            n++;
        }

        // The course is what it claims: every accepted move still slides (deterministic engine).
        for (int i = 0; i < starts.Length; i++)
        {
            ResolveResult r = engine.Resolve(starts[i], cells[i], deltas[i], World.PlayerStepUp, in options);
            if (r.Outcome != ResolveOutcome.Slid)
            {
                throw new InvalidOperationException($"Slide course move {i} no longer slides: {r}.");
            }
        }

        return $"{starts.Length} slides along {candidates.Count} walls at least {MinWallLength} m long, from {tried} draws "
            + $"(no floor beside the wall {noFloor}, body not clear {notClear}, outcomes of the rest {string.Join(", ", outcomes.Select(kv => $"{kv.Key} {kv.Value}"))}; "
            + $"slid along another wall {otherWall}; slid along it but off by more than {Tolerance} m {mismatch}{(firstMismatch is null ? string.Empty : $", first: {firstMismatch}")})";
    }

    /// <summary>A vertical wall's length, one end, the unit direction along it and its unit horizontal normal.</summary>
    private static (float Length, Vector2 A, Vector2 Along, Vector2 Normal) Extent(World.WallFace wall)
    {
        var normal = Vector2.Normalize(new Vector2(wall.Normal.X, wall.Normal.Y));
        var along = new Vector2(-normal.Y, normal.X);
        float min = float.MaxValue, max = float.MinValue;
        foreach (Vector2 p in wall.Outline)
        {
            float t = Vector2.Dot(p, along);
            min = MathF.Min(min, t);
            max = MathF.Max(max, t);
        }

        Vector2 onPlane = wall.Outline[0] - (along * Vector2.Dot(wall.Outline[0], along));
        return (max - min, onPlane + (along * min), along, normal);
    }
}
