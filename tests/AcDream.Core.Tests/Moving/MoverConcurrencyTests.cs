using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Testing;
using Xunit.Abstractions;

namespace AcDream.Core.Tests.Moving;

/// <summary>
/// Two resolver threads while a writer moves 1,000 creatures every frame (some across a seam) and opens and closes two
/// doors: every answer (with what it touched and its report) equals a single-threaded replay on one whole committed
/// state within the call's window; no exception; 0 B allocated by the resolver threads' calls.
/// </summary>
[Trait("Mutation", "MoverRegistry")]
public class MoverConcurrencyTests(ITestOutputHelper output)
{
    private const uint Landblock = 0x7A3BFFFF, East = 0x7B3BFFFF;
    private const float Ground = 50f;
    private const int Creatures = 1000, MaxFrames = 4000, CallsPerReader = 20000, Block = 2000;

    private readonly record struct Call(Vector3 Start, Vector3 Delta, int Kind, ResolveResult Answer, int Touched, uint First, MoveReport Report, int From, int To);

    private static PhysicsEngine World()
    {
        var engine = new PhysicsEngine(Landblock);
        engine.AddLandblock(Landblock, TestData.FlatTerrain(Ground, Landblock), []);
        engine.AddLandblock(East, TestData.FlatTerrain(Ground, East), []);
        return engine;
    }

    /// <summary>Creature <paramref name="i"/> in frame <paramref name="f"/>: a grid of 40 × 25 with each circling its place; column 39 is over the seam, in the east landblock.</summary>
    private static (Vector3 Position, uint Cell) Creature(PhysicsEngine engine, int i, int f)
    {
        int column = i % 40, row = i / 40;
        double a = (f * 0.15) + i;
        var local = new Vector3(4f + (column * 4.7f) + (float)(Math.Cos(a) * 0.6), 8f + (row * 7f) + (float)(Math.Sin(a) * 0.6), Ground);
        return column == 39
            ? (engine.ToWorld(East, local with { X = local.X - 192f }), 0x7B3B0000u | 0x0001)
            : (engine.ToWorld(Landblock, local), 0x7A3B0000u | 0x0001);
    }

    private static void Frame(PhysicsEngine engine, int f)
    {
        for (int i = 0; i < Creatures; i++)
        {
            (Vector3 p, uint cell) = Creature(engine, i, f);
            if (f == 0)
            {
                engine.Movers.Add((uint)(i + 1), MoverKit.Human, p, cell, MoverReference.Yaw(i), MoverState.Creature);
            }
            else
            {
                engine.Movers.Move((uint)(i + 1), p, cell, MoverReference.Yaw(i + (f * 0.1)));
            }
        }

        if (f == 0)
        {
            engine.Movers.Add(5001, new MoverShape(MoverReference.SlabModel(1.2f, 2.2f)), engine.ToWorld(Landblock, new Vector3(6.35f, 11.5f, Ground)), 0x7A3B0001, MoverReference.Yaw(0.3), MoverState.Door);
            engine.Movers.Add(5002, new MoverShape(MoverReference.SlabModel(1.2f, 2.2f)), engine.ToWorld(Landblock, new Vector3(60f, 100f, Ground)), 0x7A3B0001, Quaternion.Identity, MoverState.Door);
        }
        else if (f % 10 == 3)
        {
            engine.Movers.Open(5001);
            engine.Movers.Open(5002);
        }
        else if (f % 10 == 7)
        {
            engine.Movers.Close(5001);
            engine.Movers.Close(5002);
        }

        engine.Movers.Commit();
    }

    private static ResolveResult Ask(PhysicsEngine engine, Vector3 start, Vector3 delta, int kind, Span<uint> touched, out int count, out MoveReport report)
    {
        (count, report) = (0, default);
        return kind switch
        {
            0 => engine.Resolve(start, 0x7A3B0001, delta, 0.6f),
            1 => engine.Resolve(start, 0x7A3B0001, delta, 0.6f, MovementOptions.Player, 1u),
            _ => engine.Resolve(start, 0x7A3B0001, delta, 0.6f, MovementOptions.Player, 0u, touched, out count, out report),
        };
    }

    [Fact]
    public void Readers_see_whole_states_while_a_writer_moves_a_thousand_creatures()
    {
        PhysicsEngine engine = World();
        Frame(engine, 0);
        int done = 0, exceptions = 0;
        var calls = new Call[2][];
        long[][] allocated = [new long[CallsPerReader / Block], new long[CallsPerReader / Block]];
        var stop = new ManualResetEventSlim();
        var readers = new Thread[2];
        for (int t = 0; t < 2; t++)
        {
            int thread = t;
            calls[t] = new Call[CallsPerReader];
            readers[t] = new Thread(() =>
            {
                var random = new Random(100 + thread);
                Span<uint> touched = stackalloc uint[8];
                Call[] mine = calls[thread];
                long before = GC.GetAllocatedBytesForCurrentThread();
                for (int n = 0; n < CallsPerReader; n++)
                {
                    if (n % Block == 0 && n > 0)
                    {
                        long now = GC.GetAllocatedBytesForCurrentThread();
                        allocated[thread][(n / Block) - 1] = now - before; // each block of calls, the runtime's first-call work in the first
                        before = now;
                    }

                    var start = engine.ToWorld(Landblock, new Vector3(2f + (float)(random.NextDouble() * 188), 2f + (float)(random.NextDouble() * 180), Ground));
                    double a = random.NextDouble() * 2 * Math.PI, length = random.NextDouble() * 2.5;
                    var delta = new Vector3((float)(Math.Cos(a) * length), (float)(Math.Sin(a) * length), 0f);
                    int kind = n % 3;
                    try
                    {
                        int from = Volatile.Read(ref done);
                        ResolveResult answer = Ask(engine, start, delta, kind, touched, out int count, out MoveReport report);
                        int to = Volatile.Read(ref done);
                        mine[n] = new Call(start, delta, kind, answer, count, count > 0 ? touched[0] : 0, report, from, to);
                    }
                    catch (Exception)
                    {
                        Interlocked.Increment(ref exceptions);
                    }
                }

                allocated[thread][(CallsPerReader / Block) - 1] = GC.GetAllocatedBytesForCurrentThread() - before;
            });
        }

        foreach (Thread reader in readers)
        {
            reader.Start();
        }

        int frames = 0;
        while (frames < MaxFrames && readers.Any(r => r.IsAlive))
        {
            Frame(engine, ++frames); // as long as the readers read
            Volatile.Write(ref done, frames);
        }

        foreach (Thread reader in readers)
        {
            reader.Join();
        }

        exceptions.Should().Be(0);
        output.WriteLine($"bytes per block of {Block} calls: {string.Join(", ", allocated[0])} / {string.Join(", ", allocated[1])}");
        allocated.Should().AllSatisfy(blocks => blocks[(blocks.Length / 2)..].Should().AllSatisfy(
            bytes => bytes.Should().Be(0, $"a Resolve allocates nothing, movers or not, once the runtime's first-call work is done (the last {CallsPerReader / 2} calls of each thread, in blocks of {Block})")));

        // The replay: one engine, the writer's frames one by one; each call is answered again on every state in its window.
        PhysicsEngine replay = World();
        Call[] all = [.. calls[0], .. calls[1]];
        Array.Sort(all.Select(c => c.From).ToArray(), all);
        var matched = new bool[all.Length];
        Span<uint> again = stackalloc uint[8];
        int windows = 0, spanning = 0, open = 0;
        for (int s = 0; s <= frames; s++)
        {
            Frame(replay, s);
            while (open < all.Length && (matched[open] || all[open].To + 1 < s))
            {
                open++; // every call before this one is matched or past its window
            }

            for (int k = open; k < all.Length && all[k].From <= s; k++)
            {
                Call c = all[k];
                if (matched[k] || s > c.To + 1)
                {
                    continue;
                }

                ResolveResult answer = Ask(replay, c.Start, c.Delta, c.Kind, again, out int count, out MoveReport report);
                matched[k] = answer == c.Answer && count == c.Touched && (count == 0 || again[0] == c.First) && report == c.Report;
            }
        }

        foreach (Call c in all)
        {
            windows += c.To - c.From + 1;
            spanning += c.To > c.From ? 1 : 0;
        }

        int unmatched = matched.Count(m => !m);
        int touchedCalls = all.Count(c => c.Touched > 0), walled = all.Count(c => c.Answer.IsRefused || c.Answer.Outcome == ResolveOutcome.Slid);
        output.WriteLine($"{all.Length} calls over {frames} frames: {spanning} spanned a commit, mean window {windows / (double)all.Length:F2} states; {touchedCalls} touched a mover, {walled} stopped or slid; {unmatched} unmatched");
        int first = Array.IndexOf(matched, false);
        unmatched.Should().Be(0, first < 0 ? "" : $"call {first}: {all[first]}");
        touchedCalls.Should().BeGreaterThan(100, "the readers met the creatures");
        spanning.Should().BeGreaterThan(0, "some calls ran while the writer committed");
    }
}
