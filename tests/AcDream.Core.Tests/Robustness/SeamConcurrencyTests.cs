using System.Diagnostics;
using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using AcDream.Testing;
using Xunit.Abstractions;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Robustness;

/// <summary>
/// Seams under a writer: landblock L and its east neighbour N each have two versions whose objects and
/// building walls reach over their shared seam (L's fence into N, N's building wall and posts into L), and
/// a writer keeps replacing and removing both while two threads resolve moves near the seam (the point,
/// the body and <see cref="MovementOptions.Player"/>, swept, from both sides). Every answer must equal a
/// single-threaded replay on one whole state of the two landblocks (each A, B or absent): a change of one
/// landblock must never be seen half done, its objects in one place and not in the other.
/// </summary>
public class SeamConcurrencyTests(ITestOutputHelper output)
{
    private const uint L = 0x8080FFFFu;
    private const uint N = 0x8180FFFFu;
    private const float Ground = 10f;

    private sealed class Versions
    {
        private readonly TerrainSurface _lTerrain = FlatTerrain(Ground, L), _nTerrain = FlatTerrain(Ground, N);
        private readonly List<ObjectSurface>[] _lObjects = [Fence(100f), Fence(112f)];
        private readonly (CellSurface[] Cells, List<ObjectSurface> Objects)[] _n = [Building(96f), Building(118f)];

        /// <summary>L's fence: a wall 0.2 m thick, 1.5 m high, from x 184 to 200 (8 m into N) at y = <paramref name="y"/>.</summary>
        private static List<ObjectSurface> Fence(float y)
        {
            GfxObj fence = ObjectKit.Gfx(0x01000600,
                Wall(-8f, -0.1f, 8f, -0.1f, 0f, 1.5f), Wall(8f, 0.1f, -8f, 0.1f, 0f, 1.5f),
                Wall(8f, -0.1f, 8f, 0.1f, 0f, 1.5f), Wall(-8f, 0.1f, -8f, -0.1f, 0f, 1.5f));
            return [new ObjectSurface(fence, ObjectKit.At(new Vector3(192f, y, Ground), 0f), 0)];
        }

        /// <summary>N's building cell: a wall along y = <paramref name="y"/> from 6 m west of the seam (in L) to 4 m east, a door east; and two posts in L.</summary>
        private static (CellSurface[], List<ObjectSurface>) Building(float y)
        {
            CellSurface cell = new CellBuilder(0x81800100u, new Vector3(0f, y, Ground))
                .Physics(Wall(-6f, 0f, 4f, 0f, 0f, 3f))
                .Portal(0xFFFF, new Vector3(6.5f, 1f, 1f), new(6f, 0.5f, 0f), new(7f, 0.5f, 0f), new(7f, 0.5f, 2f), new(6f, 0.5f, 2f)).Build();
            (Setup post, Dictionary<uint, GfxObj> parts) = ObjectKit.Tree(0.3f, 3f);
            return ([cell], [new ObjectSurface(post, parts, ObjectKit.At(new Vector3(-3f, y + 5f, Ground), 0f), 0), new ObjectSurface(post, parts, ObjectKit.At(new Vector3(-8f, y - 6f, Ground), 0f), 0)]);
        }

        /// <summary>L as <paramref name="l"/>, N as <paramref name="n"/> (0 = A, 1 = B, 2 = absent).</summary>
        public void Apply(PhysicsEngine engine, int l, int n)
        {
            if (l == 2)
            {
                engine.RemoveLandblock(L);
            }
            else
            {
                engine.AddLandblock(L, _lTerrain, [], _lObjects[l]);
            }

            if (n == 2)
            {
                engine.RemoveLandblock(N);
            }
            else
            {
                engine.AddLandblock(N, _nTerrain, _n[n].Cells, _n[n].Objects);
            }
        }
    }

    private sealed record Move(Vector3 Position, uint CellId, Vector3 Delta, MovementOptions Options)
    {
        public ResolveResult Resolve(PhysicsEngine engine) => engine.Resolve(Position, CellId, Delta, 0.6f, Options);
    }

    /// <summary>Moves near the seam (x 181 to 203 of L's frame, within 2.5 m of a wall's line) on both sides, 0.1 to 4 m, with every kind of mover.</summary>
    private static List<Move> Moves()
    {
        var random = new Random(17);
        MovementOptions[] options = [MovementOptions.Literal, new() { Body = MoverBody.Player }, MovementOptions.Player, new() { Body = MoverBody.Player, SweepStepLength = 0.48f }];
        var moves = new List<Move>();
        for (int i = 0; i < 320; i++)
        {
            float[] walls = [96f, 100f, 112f, 118f, 101f, 90f, 123f]; // the fences, the building walls, the posts
            float x = (float)Gen.Range(random, 181, 203), y = walls[random.Next(walls.Length)] + (float)Gen.Range(random, -2.5, 2.5);
            double angle = random.NextDouble() * 2 * Math.PI, length = Gen.Range(random, 0.1, 4);
            var delta = new Vector3((float)(length * Math.Cos(angle)), (float)(length * Math.Sin(angle)), 0f);
            moves.Add(new Move(new Vector3(x, y, Ground), x < 192f ? 0x80800000u : 0x81800000u, delta, options[i % options.Length]));
        }

        return moves;
    }

    private static bool Same(in ResolveResult a, in ResolveResult b) =>
        Bits(a.Position) == Bits(b.Position) && a.CellId == b.CellId && a.IsOnGround == b.IsOnGround
        && a.Outcome == b.Outcome && Bits(a.SurfaceNormal) == Bits(b.SurfaceNormal);

    private static (int, int, int) Bits(Vector3 v) =>
        (BitConverter.SingleToInt32Bits(v.X), BitConverter.SingleToInt32Bits(v.Y), BitConverter.SingleToInt32Bits(v.Z));

    [Fact]
    public void Resolve_NearASeamWhileAWriterChurnsBothSides_EveryAnswerIsAWholeStatesReplay()
    {
        var versions = new Versions();
        var engine = new PhysicsEngine(L);
        List<Move> moves = Moves();
        var answers = new ResolveResult[moves.Count][];
        for (int m = 0; m < moves.Count; m++)
        {
            answers[m] = new ResolveResult[9];
        }

        for (int state = 0; state < 9; state++)
        {
            versions.Apply(engine, state / 3, state % 3);
            for (int m = 0; m < moves.Count; m++)
            {
                answers[m][state] = moves[m].Resolve(engine);
            }
        }

        // The states matter: most moves answer differently in some of them, and the seam's walls stop many.
        int differing = moves.Count(m => answers[moves.IndexOf(m)].Distinct().Count() > 1);
        int stopped = answers.Count(a => a.Any(r => r.Outcome is ResolveOutcome.Slid or ResolveOutcome.Wall));
        differing.Should().BeGreaterThan(moves.Count / 3, "the versions change the answers");
        stopped.Should().BeGreaterThan(moves.Count / 8, "walls reaching over the seam stop or turn moves");

        versions.Apply(engine, 0, 0);
        var errors = new List<Exception>();
        var mismatches = new List<string>();
        long mismatchCount = 0, resolves = 0, changes = 0;
        bool stop = false;
        var writer = new Thread(() =>
        {
            int[] sequence = [0, 1, 2, 1, 0, 2];
            try
            {
                for (long i = 0; !Volatile.Read(ref stop); i++)
                {
                    versions.Apply(engine, sequence[i % 6], sequence[(i / 5) % 6]);
                    Interlocked.Increment(ref changes);
                }
            }
            catch (Exception e)
            {
                lock (errors)
                {
                    errors.Add(e);
                }
            }
        }) { IsBackground = true };
        var resolvers = new Thread[2];
        for (int t = 0; t < resolvers.Length; t++)
        {
            int thread = t;
            resolvers[t] = new Thread(() =>
            {
                try
                {
                    var clock = Stopwatch.StartNew();
                    for (int m = thread * 100; clock.ElapsedMilliseconds < 3000; m = (m + 1) % moves.Count)
                    {
                        ResolveResult r = moves[m].Resolve(engine);
                        Interlocked.Increment(ref resolves);
                        if (!answers[m].Any(a => Same(a, r)) && Interlocked.Increment(ref mismatchCount) <= 10)
                        {
                            lock (mismatches)
                            {
                                mismatches.Add($"move {m} ({moves[m]}): got {r}; a replay gives one of {string.Join(", ", answers[m].Distinct())}");
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
            }) { IsBackground = true };
        }

        writer.Start();
        foreach (Thread t in resolvers)
        {
            t.Start();
        }

        foreach (Thread t in resolvers)
        {
            t.Join();
        }

        Volatile.Write(ref stop, true);
        writer.Join();
        string summary = $"{resolves:N0} resolves of {moves.Count} moves ({differing} differ by state, {stopped} stopped in some) while the writer made {changes:N0} changes; {mismatchCount} mismatches";
        output.WriteLine(summary);
        errors.Should().BeEmpty(summary);
        mismatchCount.Should().Be(0, $"{summary}\n{string.Join("\n", mismatches)}");
        changes.Should().BeGreaterThan(1000, summary);
        resolves.Should().BeGreaterThan(100_000, summary);
    }
}
