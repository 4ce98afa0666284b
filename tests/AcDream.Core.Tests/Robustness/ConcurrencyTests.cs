using System.Diagnostics;
using System.Numerics;
using AcDream.Core.Physics;
using Xunit.Abstractions;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Robustness;

/// <summary>
/// Many movers at once (issue 9): two threads resolve while a writer keeps replacing and removing
/// the landblocks they stand on. Every answer must be the answer of a single-threaded replay of one
/// snapshot, and resolving must allocate nothing meanwhile.
/// </summary>
/// <remarks>
/// Landblock L has two versions that give a different answer to every move inside it: A (terrain
/// flat at 10 m, two connected rooms in the west) and B (terrain at 13 m, the same two cell ids
/// placed in the east with their floors 0.3 m up). Its east neighbour N has versions A′ (10.5 m)
/// and B′ (12 m). Every move is resolved single-threaded against each of the 3 × 3 states (each
/// landblock as A, B or absent); a move inside L must give the same answer whatever N is, so its
/// answer names L's snapshot. A move across the L–N seam reads both landblocks, each whole but
/// possibly from different moments, so any of its nine answers is allowed.
/// </remarks>
public class ConcurrencyTests(ITestOutputHelper output)
{
    private const uint L = 0x8080FFFFu;
    private const uint N = 0x8180FFFFu;
    private const int Absent = 2;

    private static readonly string[] Kinds = ["A", "B", "absent"];

    /// <summary>The landblock versions, built once: a writer publishes the same objects over and over.</summary>
    private sealed class Versions
    {
        public TerrainSurface[] LTerrain { get; } = [FlatTerrain(10f, L), FlatTerrain(13f, L)];

        public CellSurface[][] LCells { get; } =
        [
            Rooms(new Vector3(40f, 40f, 10f)),
            Rooms(new Vector3(120f, 100f, 13.3f)),
        ];

        public TerrainSurface[] NTerrain { get; } = [FlatTerrain(10.5f, N), FlatTerrain(12f, N)];

        /// <summary>Puts L in version <paramref name="l"/> and N in <paramref name="n"/> (0 = A, 1 = B, 2 = absent).</summary>
        public void Apply(PhysicsEngine engine, int l, int n)
        {
            if (l == Absent)
            {
                engine.RemoveLandblock(L);
            }
            else
            {
                engine.AddLandblock(L, LTerrain[l], LCells[l]);
            }

            if (n == Absent)
            {
                engine.RemoveLandblock(N);
            }
            else
            {
                engine.AddLandblock(N, NTerrain[n], []);
            }
        }
    }

    /// <summary>One move; <see cref="InL"/>: it starts and ends inside L, so it reads L only.</summary>
    private sealed record Move(Vector3 Position, uint CellId, Vector3 Delta, float StepUp, MovementOptions Options, bool InL)
    {
        public ResolveResult Resolve(PhysicsEngine engine) => engine.Resolve(Position, CellId, Delta, StepUp, Options);

        public override string ToString() =>
            $"from {Position:R} in 0x{CellId:X8} by {Delta:R}, step {StepUp}, {Options}";
    }

    /// <summary>
    /// Two rooms, cells 0x0100 and 0x0101 of L, 8 m square, 0x0101 north of 0x0100, a 2 m doorway
    /// between them and one from 0x0100 to the outdoors in its south wall.
    /// </summary>
    private static CellSurface[] Rooms(Vector3 origin)
    {
        const float size = 8f, mid = size / 2;
        var inside = new Vector3(mid, mid, 1f);
        var south = new CellBuilder((L & 0xFFFF0000u) | 0x0100u, origin);
        south.Floor(0, 0, size, size, 0);
        south.Portal(0xFFFF, inside, new(mid - 1, 0, 0), new(mid + 1, 0, 0), new(mid + 1, 0, 2.5f), new(mid - 1, 0, 2.5f));
        south.Portal(0x0101, inside, new(mid - 1, size, 0), new(mid + 1, size, 0), new(mid + 1, size, 2.5f), new(mid - 1, size, 2.5f));
        var north = new CellBuilder((L & 0xFFFF0000u) | 0x0101u, origin + new Vector3(0, size, 0));
        north.Floor(0, 0, size, size, 0);
        north.Portal(0x0100, inside, new(mid - 1, 0, 0), new(mid + 1, 0, 0), new(mid + 1, 0, 2.5f), new(mid - 1, 0, 2.5f));
        return [south.Build(), north.Build()];
    }

    /// <summary>
    /// Outdoor moves over L (anywhere, and near either version's rooms), indoor moves in both rooms
    /// as placed by either version (within a room, to the other room, into a wall, out of the door),
    /// and moves across the L–N seam both ways. No sweeps: see the remarks of <see cref="PhysicsEngine"/>.
    /// </summary>
    private static List<Move> Moves()
    {
        var random = new Random(9);
        MovementOptions[] options = [default, new() { StepDownHeight = 1.5f }, new() { WalkableSlope = true }, new() { DoorsOnly = true }];
        float[] steps = [0.5f, 5f];
        var moves = new List<Move>();
        for (int i = 0; i < 300; i++)
        {
            MovementOptions option = options[random.Next(options.Length)];
            float step = steps[random.Next(steps.Length)];
            float x, y, z;
            switch (i % 6)
            {
                case 0 or 1: // outdoors anywhere in L, at least 8 m from its edges
                    (x, y, z) = (Gen.Range(random, 8, 184), Gen.Range(random, 8, 184), Gen.Range(random, 9.5, 13.5));
                    moves.Add(new Move(new Vector3(x, y, z), random.Next(2) == 0 ? 0u : Outdoor(L, x, y), World(random, 0.1, 6), step, option, InL: true));
                    break;
                case 2: // outdoors around one version's rooms (16 m × 24 m from 4 m outside them)
                    bool b = random.Next(2) == 1;
                    (x, y) = (Gen.Range(random, -4, 12) + (b ? 120f : 40f), Gen.Range(random, -4, 20) + (b ? 100f : 40f));
                    z = b ? 13f : 10f;
                    moves.Add(new Move(new Vector3(x, y, z), Outdoor(L, x, y), World(random, 0.1, 4), step, option, InL: true));
                    break;
                case 3: // indoors, in either room as placed by either version
                    bool inB = random.Next(2) == 1;
                    uint cell = (L & 0xFFFF0000u) | (uint)(0x0100 + random.Next(2));
                    float north = (cell & 1) == 1 ? 8f : 0f;
                    (x, y) = (Gen.Range(random, 0.2, 7.8) + (inB ? 120f : 40f), Gen.Range(random, 0.2, 7.8) + north + (inB ? 100f : 40f));
                    moves.Add(new Move(new Vector3(x, y, inB ? 13.3f : 10f), cell, World(random, 0.1, 6), step, option, InL: true));
                    break;
                case 4: // out of the south room's door onto L's terrain, as placed by either version
                    bool outB = random.Next(2) == 1;
                    (x, y) = (Gen.Range(random, 3.2, 4.8) + (outB ? 120f : 40f), Gen.Range(random, 0.2, 1.5) + (outB ? 100f : 40f));
                    moves.Add(new Move(new Vector3(x, y, outB ? 13.3f : 10f), (L & 0xFFFF0000u) | 0x0100u, new Vector3(Gen.Range(random, -0.3, 0.3), Gen.Range(random, -3, -1.6), 0f), step, option, InL: true));
                    break;
                default: // across the east seam of L, from either side
                    bool fromL = random.Next(2) == 0;
                    (x, y, z) = (fromL ? Gen.Range(random, 186, 191.9) : Gen.Range(random, 192.1, 198), Gen.Range(random, 8, 184), Gen.Range(random, 9.5, 13.5));
                    float dx = Gen.Range(random, 0.5, 8) * (fromL ? 1 : -1);
                    uint from = random.Next(2) == 0 ? 0u : fromL ? Outdoor(L, x, y) : Outdoor(N, x - 192f, y);
                    moves.Add(new Move(new Vector3(x, y, z), from, new Vector3(dx, Gen.Range(random, -1, 1), 0f), step, option, InL: false));
                    break;
            }
        }

        return moves;

        static uint Outdoor(uint landblock, float x, float y) =>
            (landblock & 0xFFFF0000u) | (uint)((Math.Clamp((int)(x / 24f), 0, 7) * 8) + Math.Clamp((int)(y / 24f), 0, 7) + 1);

        static Vector3 World(Random random, double min, double max)
        {
            double angle = random.NextDouble() * 2 * Math.PI, length = min + (random.NextDouble() * (max - min));
            return new Vector3((float)(length * Math.Cos(angle)), (float)(length * Math.Sin(angle)), 0f);
        }
    }

    /// <summary>Every move resolved single-threaded in each of the nine states: answers[move][l·3 + n].</summary>
    private static ResolveResult[][] Replay(PhysicsEngine engine, Versions versions, List<Move> moves)
    {
        var answers = new ResolveResult[moves.Count][];
        for (int m = 0; m < moves.Count; m++)
        {
            answers[m] = new ResolveResult[9];
        }

        for (int l = 0; l < 3; l++)
        {
            for (int n = 0; n < 3; n++)
            {
                versions.Apply(engine, l, n);
                for (int m = 0; m < moves.Count; m++)
                {
                    answers[m][(l * 3) + n] = moves[m].Resolve(engine);
                }
            }
        }

        return answers;
    }

    /// <summary>The whole result, bit for bit (position and normal by their float bits, so −0 ≠ +0).</summary>
    private static bool Same(in ResolveResult a, in ResolveResult b) =>
        Bits(a.Position) == Bits(b.Position) && a.CellId == b.CellId && a.IsOnGround == b.IsOnGround
        && a.Outcome == b.Outcome && Bits(a.SurfaceNormal) == Bits(b.SurfaceNormal);

    private static (int, int, int) Bits(Vector3 v) =>
        (BitConverter.SingleToInt32Bits(v.X), BitConverter.SingleToInt32Bits(v.Y), BitConverter.SingleToInt32Bits(v.Z));

    /// <summary>The writer: L and N through A, B, absent, B, A, absent (every transition), out of step with each other.</summary>
    private static Thread Writer(PhysicsEngine engine, Versions versions, Func<bool> stop, long[] changes, List<Exception> errors) =>
        new(() =>
        {
            int[] sequence = [0, 1, Absent, 1, 0, Absent];
            try
            {
                for (long i = 0; !stop(); i++)
                {
                    versions.Apply(engine, sequence[i % 6], sequence[(i / 5) % 6]);
                    Interlocked.Increment(ref changes[0]);
                }
            }
            catch (Exception e)
            {
                lock (errors)
                {
                    errors.Add(e);
                }
            }
        })
        { IsBackground = true, Name = "landblock writer" };

    [Fact]
    public void Resolve_TwoThreadsWhileAWriterChurnsLandblocks_EveryAnswerIsASnapshotsReplay()
    {
        var versions = new Versions();
        var engine = new PhysicsEngine(L);
        List<Move> moves = Moves();
        ResolveResult[][] answers = Replay(engine, versions, moves);

        // The design holds: a move inside L reads only L (its answer does not depend on N), and its
        // answers under A, B and absent differ, so each answer names the snapshot it came from.
        int inL = 0;
        for (int m = 0; m < moves.Count; m++)
        {
            if (!moves[m].InL)
            {
                continue;
            }

            inL++;
            for (int l = 0; l < 3; l++)
            {
                for (int n = 1; n < 3; n++)
                {
                    Same(answers[m][l * 3], answers[m][(l * 3) + n]).Should().BeTrue(
                        $"move {m} ({moves[m]}) stays in L: with L {Kinds[l]}, N {Kinds[n]} gives {answers[m][(l * 3) + n]}, N A gives {answers[m][l * 3]}");
                }
            }

            Same(answers[m][0], answers[m][3]).Should().BeFalse($"move {m} ({moves[m]}): A and B both give {answers[m][0]}");
            answers[m][6].Outcome.Should().Be(ResolveOutcome.Held, $"move {m} ({moves[m]}) with L absent");
        }

        inL.Should().BeGreaterThan(150);

        versions.Apply(engine, 0, 0);
        const int resolvers = 2;
        TimeSpan duration = TimeSpan.FromSeconds(3);
        var errors = new List<Exception>();
        var mismatches = new List<string>();
        long[] mismatchCount = new long[resolvers], resolves = new long[resolvers], seamResolves = new long[resolvers], switches = new long[resolvers];
        long[][] seen = [new long[3], new long[3]];
        long[] changes = new long[1];
        int running = resolvers;
        Thread writer = Writer(engine, versions, () => Volatile.Read(ref running) == 0, changes, errors);
        var threads = new Thread[resolvers];
        for (int t = 0; t < resolvers; t++)
        {
            int thread = t;
            threads[t] = new Thread(() =>
            {
                try
                {
                    var clock = Stopwatch.StartNew();
                    int last = -1;
                    for (int m = thread * (moves.Count / 2); clock.Elapsed < duration; m = m + 1 == moves.Count ? 0 : m + 1)
                    {
                        ResolveResult r = moves[m].Resolve(engine);
                        resolves[thread]++;
                        int match = -1;
                        if (moves[m].InL)
                        {
                            for (int l = 0; l < 3 && match < 0; l++)
                            {
                                match = Same(r, answers[m][l * 3]) ? l : -1;
                            }

                            if (match >= 0)
                            {
                                seen[thread][match]++;
                                switches[thread] += last >= 0 && last != match ? 1 : 0;
                                last = match;
                            }
                        }
                        else
                        {
                            seamResolves[thread]++;
                            for (int s = 0; s < 9 && match < 0; s++)
                            {
                                match = Same(r, answers[m][s]) ? s : -1;
                            }
                        }

                        if (match < 0 && ++mismatchCount[thread] <= 10)
                        {
                            lock (mismatches)
                            {
                                mismatches.Add($"thread {thread}, move {m} ({moves[m]}): got {r}; a replay gives one of {string.Join(", ", answers[m].Distinct())}");
                            }
                        }
                    }
                }
                catch (Exception e)
                {
                    lock (errors)
                    {
                        errors.Add(e);
                    }
                }
                finally
                {
                    Interlocked.Decrement(ref running);
                }
            })
            { IsBackground = true, Name = $"resolver {t}" };
        }

        writer.Start();
        foreach (Thread thread in threads)
        {
            thread.Start();
        }

        foreach (Thread thread in threads)
        {
            thread.Join();
        }

        writer.Join();

        string summary = $"{moves.Count} moves ({inL} inside L); writer made {changes[0]:N0} changes; " + string.Join("; ", Enumerable.Range(0, resolvers).Select(t =>
            $"resolver {t}: {resolves[t]:N0} resolves ({seamResolves[t]:N0} across the seam), inside L saw A {seen[t][0]:N0}, B {seen[t][1]:N0}, absent {seen[t][2]:N0}, switched snapshot {switches[t]:N0} times, {mismatchCount[t]} mismatches"));
        output.WriteLine(summary);
        errors.Should().BeEmpty(summary);
        mismatchCount.Sum().Should().Be(0, $"{summary}\n{string.Join("\n", mismatches)}");
        for (int t = 0; t < resolvers; t++)
        {
            seen[t].Should().OnlyContain(count => count >= 1000, $"resolver {t} must see every snapshot of L many times: {summary}");
            switches[t].Should().BeGreaterThanOrEqualTo(100, $"resolver {t} must see L change under it many times: {summary}");
        }
    }

    [Fact]
    public void Resolve_WhileAWriterChurnsLandblocks_AllocatesNothing()
    {
        var versions = new Versions();
        var engine = new PhysicsEngine(L);
        List<Move> moves = Moves();
        versions.Apply(engine, 0, 0);
        var errors = new List<Exception>();
        long[] changes = new long[1];
        bool stop = false;
        Thread writer = Writer(engine, versions, () => Volatile.Read(ref stop), changes, errors);
        writer.Start();
        try
        {
            // Warm up (JIT tiering, every path under every snapshot), then count a steady-state run.
            var clock = Stopwatch.StartNew();
            float sink = 0f;
            while (clock.ElapsedMilliseconds < 300)
            {
                sink += Run(engine, moves);
            }

            long changesBefore = Volatile.Read(ref changes[0]);
            long before = GC.GetAllocatedBytesForCurrentThread();
            int passes = 0;
            for (clock.Restart(); clock.ElapsedMilliseconds < 500; passes++)
            {
                sink += Run(engine, moves);
            }

            long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
            long churned = Volatile.Read(ref changes[0]) - changesBefore;
            string what = $"{passes * moves.Count:N0} resolves while the writer made {churned:N0} changes (sink {sink})";
            output.WriteLine(what);
            churned.Should().BeGreaterThan(100, what);
            allocated.Should().Be(0, $"{what} allocated {allocated} bytes");
        }
        finally
        {
            Volatile.Write(ref stop, true);
            writer.Join();
        }

        errors.Should().BeEmpty();

        static float Run(PhysicsEngine engine, List<Move> moves)
        {
            float sink = 0f;
            foreach (Move move in moves)
            {
                sink += move.Resolve(engine).Position.Z;
            }

            return sink;
        }
    }
}
