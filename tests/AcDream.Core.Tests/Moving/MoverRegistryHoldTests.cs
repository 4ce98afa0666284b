using System.Numerics;
using AcDream.Core.Physics;

namespace AcDream.Core.Tests.Moving;

/// <summary>
/// The registry's committed states as readers hold them and as a commit files them: a reader that holds and releases
/// states while the writer commits leaves no state held (the writer keeps reusing three states and allocates nothing),
/// and a state's tables have at least twice as many slots as it has movers, however many that is.
/// </summary>
[Trait("Mutation", "MoverRegistry")]
public class MoverRegistryHoldTests
{
    private const uint Outdoor = 0x7A3B0025;

    private static Vector3 At(PhysicsEngine engine, float x, float y) =>
        engine.ToWorld(MoverSmokeTests.Landblock, new Vector3(x, y, MoverSmokeTests.Ground));

    [Fact]
    public void A_reader_holding_states_while_the_writer_commits_leaves_none_held_and_the_writer_adds_at_most_a_few_states()
    {
        PhysicsEngine engine = MoverSmokeTests.Field();
        MoverRegistry movers = engine.Movers;
        movers.Add(1, MoverKit.Human, At(engine, 100f, 100f), Outdoor, Quaternion.Identity, MoverState.Creature);

        // Three states, the most one reader needs: the current one, one it holds and one to write.
        movers.Commit();
        MoverFrame first = movers.Hold()!;
        movers.Commit();
        MoverFrame second = movers.Hold()!;
        movers.Commit();
        MoverRegistry.Release(first);
        MoverRegistry.Release(second);

        bool stop = false;
        long holds = 0, none = 0;
        var reader = new Thread(() =>
        {
            while (!Volatile.Read(ref stop))
            {
                MoverFrame? held = movers.Hold();
                none += held is null ? 1 : 0;
                MoverRegistry.Release(held);
                Interlocked.Increment(ref holds);
            }
        });
        reader.Start();
        while (Interlocked.Read(ref holds) == 0)
        {
            Thread.Yield(); // the reader is running
        }

        for (int warm = 0; warm < 100; warm++)
        {
            movers.Commit();
        }

        // Each commit publishes another state while the reader holds and releases the current one: whenever the
        // state changes between a hold's read and its recheck, the hold is undone.
        int commits = 0;
        var clock = System.Diagnostics.Stopwatch.StartNew();
        long before = GC.GetAllocatedBytesForCurrentThread();
        while (commits < 100000 && clock.ElapsedMilliseconds < 2000)
        {
            movers.Move(1, At(engine, 100f + (0.01f * (commits % 7)), 100f), Outdoor, Quaternion.Identity);
            movers.Commit();
            commits++;
        }

        long bytes = GC.GetAllocatedBytesForCurrentThread() - before;
        Volatile.Write(ref stop, true);
        reader.Join();
        none.Should().Be(0, "a mover is committed throughout");

        // Three states suffice, each free again once released; a commit may add one more only when the reader, preempted
        // inside a hold, has every spare state counted at that instant (MoverRegistry's remarks): a few states at most,
        // however many commits (one is about 8 KB here). A hold whose undo leaked would leave states held for good and
        // make the writer add one at nearly every commit.
        bytes.Should().BeLessThan(32 * 1024, $"{commits} commits while the reader held {Interlocked.Read(ref holds)} states, one at a time: at most a few spare states are ever added");
        MoverFrame now = movers.Hold()!;
        now.Readers.Should().Be(1, "held once, by this call");
        MoverRegistry.Release(now);
        movers.Commit();
        movers.Commit();
        movers.Commit();
        foreach (MoverFrame frame in new[] { first, second, now })
        {
            frame.Readers.Should().Be(0, "no one holds it");
        }
    }

    [Theory]
    [InlineData(1)]
    [InlineData(32)]
    [InlineData(33)]
    [InlineData(40)]
    [InlineData(63)]
    public void A_state_has_at_least_twice_as_many_slots_as_movers_in_its_tables(int n)
    {
        PhysicsEngine engine = MoverSmokeTests.Field();
        MoverRegistry movers = engine.Movers;
        for (uint i = 1; i <= n; i++)
        {
            movers.Add(i, MoverKit.Human, At(engine, 2f + (2.5f * ((i - 1) % 40)), 20f + (3f * ((i - 1) / 40))), Outdoor, Quaternion.Identity, MoverState.Creature);
        }

        movers.Commit();
        MoverFrame frame = movers.Hold()!;
        MoverRegistry.Release(frame);
        int slots = frame.Mask + 1;
        frame.Count.Should().Be(n);
        (slots & (slots - 1)).Should().Be(0, $"{slots} slots: a power of two");
        slots.Should().BeGreaterThanOrEqualTo(Math.Max(64, 2 * n));
        frame.Heads.Length.Should().Be(slots + 1);
        frame.ById.Length.Should().Be(slots);
        frame.FiledCells.Length.Should().BeGreaterThanOrEqualTo(slots);
        for (uint i = 1; i <= n; i++)
        {
            frame.StateOf(i).Should().Be(MoverState.Creature, $"mover {i}");
        }

        frame.StateOf((uint)n + 1).Should().Be(MoverState.Unregistered);
    }
}
