using System.Numerics;
using AcDream.Core.Physics;

namespace AcDream.Core.Tests.Moving;

/// <summary>
/// With no movers committed every answer is the engine's without movers, bit for bit; and so it is with movers
/// committed where no move can meet them (the movers' queries run and find nothing), in both world frames.
/// </summary>
[Trait("Mutation", "MoverRegistry")]
public class MoverZeroCostTests
{
    [Theory]
    [InlineData("centred")]
    [InlineData("global")]
    public void Answers_are_bit_identical_with_no_movers_and_with_movers_out_of_reach(string frame)
    {
        (PhysicsEngine plain, _) = HoltburgCells.OnHills(new Random(5), frame);
        (PhysicsEngine emptied, _) = HoltburgCells.OnHills(new Random(5), frame);
        (PhysicsEngine far, _) = HoltburgCells.OnHills(new Random(5), frame);

        // Registered, committed, then all removed and committed: no movers again.
        emptied.Movers.Add(3, MoverKit.Human, emptied.ToWorld(TestData.Holtburg, new Vector3(96f, 96f, 120f)), 0xA9B40001, Quaternion.Identity, MoverState.Creature);
        emptied.Movers.Commit();
        emptied.Movers.Remove(3);
        emptied.Movers.Commit();

        // 200 creatures four landblocks away: committed, never near a move here.
        for (uint i = 1; i <= 200; i++)
        {
            far.Movers.Add(i, MoverKit.Human, far.ToWorld(0xADB4FFFF, new Vector3(i % 190, i / 2f, 60f)), 0xADB40001, Quaternion.Identity, MoverState.Creature);
        }

        far.Movers.Commit();
        var random = new Random(7);
        Vector3 origin = plain.GetLandblockOrigin(TestData.Holtburg);
        uint[] cells = [.. HoltburgCells.Fixtures.Keys];
        MovementOptions[] options = [default, MovementOptions.Player, MovementOptions.Player with { Body = null }, new() { Body = MoverBody.Player, SweepStepLength = 0.48f }];
        Span<uint> touched = stackalloc uint[4];
        for (int n = 0; n < 3000; n++)
        {
            (Vector3 pos, uint cell) = HoltburgCells.RandomStart(random, origin, cells, indoor: n % 2 == 1);
            var delta = new Vector3((float)(random.NextDouble() * 4) - 2, (float)(random.NextDouble() * 4) - 2, (float)(random.NextDouble() * 2) - 1);
            float step = (float)(random.NextDouble() * 2);
            MovementOptions o = options[n % options.Length];
            string what = $"case {n}: {pos} in 0x{cell:X8} moving {delta}, step {step}, {o}";

            ResolveResult literal = plain.Resolve(pos, cell, delta, step);
            ResolveResult with = plain.Resolve(pos, cell, delta, step, o, out MoveReport report);
            foreach (PhysicsEngine engine in new[] { emptied, far })
            {
                engine.Resolve(pos, cell, delta, step).Should().Be(literal, what);
                engine.Resolve(pos, cell, delta, step, o).Should().Be(with, what);
                engine.Resolve(pos, cell, delta, step, o, 5u).Should().Be(with, what);
                engine.Resolve(pos, cell, delta, step, o, 5u, touched, out int count, out MoveReport other).Should().Be(with, what);
                other.Should().Be(report, what);
                count.Should().Be(0, what);
            }
        }
    }
}
