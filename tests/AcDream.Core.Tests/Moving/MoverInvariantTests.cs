using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Testing;
using Xunit.Abstractions;

namespace AcDream.Core.Tests.Moving;

/// <summary>
/// Random walks of a body among creatures and a door on open ground, in both world frames: every answer is a fixed point
/// (resolved again with a zero delta it is returned bit for bit), stands on the ground exactly when its Z is the
/// ground's, keeps the body out of every creature (double precision), and where a double-precision sweep says the body
/// could not have touched a mover, equals the answer of the same engine without movers, bit for bit.
/// </summary>
[Trait("Mutation", "MoverRegistry")]
public class MoverInvariantTests(ITestOutputHelper output)
{
    [Theory]
    [InlineData("centred", 1)]
    [InlineData("centred", 2)]
    [InlineData("global", 3)]
    [InlineData("global", 4)]
    public void Walks_among_creatures_keep_the_invariants_and_agree_with_the_reference(string frame, int seed)
    {
        const uint landblock = MoverSmokeTests.Landblock, cell = MoverSmokeTests.Outdoor;
        const float ground = MoverSmokeTests.Ground;
        PhysicsEngine engine = MoverSmokeTests.Field(frame), bare = MoverSmokeTests.Field(frame);
        var random = new Random(seed);
        var creatures = new List<Vector3>();
        for (uint i = 1; i <= 60; i++)
        {
            var p = engine.ToWorld(landblock, new Vector3(85f + (float)(random.NextDouble() * 20), 85f + (float)(random.NextDouble() * 20), ground));
            engine.Movers.Add(i, MoverKit.Human, p, cell, MoverReference.Yaw(random.NextDouble() * 6), MoverState.Creature);
            creatures.Add(p);
        }

        engine.Movers.Commit();
        ResolveResult Among()
        {
            while (true)
            {
                var p = engine.ToWorld(landblock, new Vector3(85f + (float)(random.NextDouble() * 20), 85f + (float)(random.NextDouble() * 20), ground));
                if (creatures.All(c => MoverReference.Apart(p, c) > 1.0))
                {
                    return new ResolveResult(p, cell, true);
                }
            }
        }

        ResolveResult at = Among();
        int free = 0, compared = 0, met = 0;
        double nearest = double.MaxValue;
        for (int n = 0; n < 3000; n++)
        {
            double a = random.NextDouble() * 2 * Math.PI, length = random.NextDouble() * (n % 7 == 0 ? 1.6 : 0.3);
            var delta = new Vector3((float)(Math.Cos(a) * length), (float)(Math.Sin(a) * length), 0f);
            ResolveResult r = engine.Resolve(at.Position, at.CellId, delta, 0.6f, MovementOptions.Player);
            string what = $"seed {seed} move {n}: from {at.Position} by {delta}: {r}";
            engine.Resolve(r.Position, r.CellId, Vector3.Zero, 0.6f, MovementOptions.Player).Should().Be(r with { Outcome = ResolveOutcome.Moved, SurfaceNormal = default }, what);
            r.IsOnGround.Should().Be(Math.Abs(r.Position.Z - ground) <= PhysicsConstants.GroundTolerance, what);
            foreach (Vector3 c in creatures)
            {
                double apart = MoverReference.Apart(r.Position, c);
                nearest = Math.Min(nearest, apart);
                apart.Should().BeGreaterThanOrEqualTo(0.96 - 0.001, what);
            }

            // The reference: the body's straight path without movers, swept against every creature in double precision.
            ResolveResult alone = bare.Resolve(at.Position, at.CellId, delta, 0.6f, MovementOptions.Player);
            if (creatures.Min(c => MoverReference.SegmentTo(at.Position, alone.Position, c)) > 0.96 + 0.01)
            {
                // Within one sweep step the body's free path is the point move's, bit for bit; a longer one aims its
                // sub-steps along the planned path (as it does beside any wall), which may round differently.
                if (length <= 0.47)
                {
                    r.Should().Be(alone, $"{what}: no creature within reach of the path");
                }
                else
                {
                    // Each of its (at most four) sub-steps rounds once in the world frame: within four units in the last place.
                    float ulp = MathF.BitIncrement(MathF.Max(MathF.Abs(r.Position.X), MathF.Abs(r.Position.Y))) - MathF.Max(MathF.Abs(r.Position.X), MathF.Abs(r.Position.Y));
                    MathF.Abs(r.Position.X - alone.Position.X).Should().BeLessThanOrEqualTo(1e-4f + (4f * ulp), $"{what}: no creature within reach of the path");
                    MathF.Abs(r.Position.Y - alone.Position.Y).Should().BeLessThanOrEqualTo(1e-4f + (4f * ulp), $"{what}: no creature within reach of the path");
                    r.Outcome.Should().Be(alone.Outcome, what);
                }

                free++;
            }
            else
            {
                met++;
            }

            compared++;
            at = n % 50 == 49 ? Among() : r; // a fresh start among them now and then
        }

        output.WriteLine($"seed {seed}, {frame}: {compared} moves, {free} free and equal to the bare engine, {met} near a creature; nearest centre distance {nearest:F6} m");
        free.Should().BeGreaterThan(300);
        met.Should().BeGreaterThan(200, "the walks came near the creatures");
    }
}
