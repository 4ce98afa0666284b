using System.Numerics;
using AcDream.Core.Physics;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// Default options are the literal engine: <c>Resolve</c> with default options, <see cref="MovementOptions.Literal"/>
/// or options naming no body answers bit for bit as the four-argument call, in both world frames; and a body
/// touching nothing changes no answer.
/// </summary>
[Trait("Mutation", "PortalTraversal")]
public class DefaultOptionsTests
{
    [Theory]
    [InlineData("centred")]
    [InlineData("global")]
    public void Resolve_DefaultOptions_BitIdenticalToTheLiteralCall(string frame)
    {
        // 5,000 random movers outdoors and in every real cell: default options, the literal options, and
        // options with the body named and absent, each against the four-argument call.
        var random = new Random(5);
        (PhysicsEngine engine, _) = HoltburgCells.OnHills(random, frame);
        Vector3 origin = engine.GetLandblockOrigin(TestData.Holtburg);
        uint[] cells = [.. HoltburgCells.Fixtures.Keys];
        for (int n = 0; n < 5000; n++)
        {
            (Vector3 pos, uint cell) = HoltburgCells.RandomStart(random, origin, cells, indoor: n % 2 == 1);
            var delta = new Vector3((float)(random.NextDouble() * 4) - 2, (float)(random.NextDouble() * 4) - 2, 0);
            float step = (float)(random.NextDouble() * 2);

            ResolveResult literal = engine.Resolve(pos, cell, delta, step);
            string what = $"case {n}: {pos} in 0x{cell:X8} moving {delta}, step {step}";
            engine.Resolve(pos, cell, delta, step, default).Should().Be(literal, what);
            engine.Resolve(pos, cell, delta, step, MovementOptions.Literal).Should().Be(literal, what);
            engine.Resolve(pos, cell, delta, step, new MovementOptions { Body = null }).Should().Be(literal, what);
            engine.Resolve(pos, cell, delta, step, MovementOptions.Literal with { Body = null }).Should().Be(literal, what);
        }
    }

    [Theory]
    [InlineData("centred")]
    [InlineData("global")]
    public void Resolve_BodyTouchingNothing_BitIdenticalToNoBody(string frame)
    {
        // Outdoors on the hills, 25 m and more from any building, moves no longer than a sweep step: with or
        // without the player's body every effect gives the same answer, bit for bit (the body's path with no
        // contact is the point move itself; a longer swept one aims its sub-steps along the path instead).
        // Walkable slope is left out: with a body a slope too steep to climb is slid along, by design; so are the body's
        // effects in three dimensions (these starts are in mid-air, where vertical motion keeps a body).
        var random = new Random(6);
        (PhysicsEngine engine, _) = HoltburgCells.OnHills(random, frame);
        Vector3 origin = engine.GetLandblockOrigin(TestData.Holtburg);
        MovementOptions[] configurations =
        [
            default,
            new() { StepDownHeight = 1.5f },
            new() { SweepStepLength = 0.48f },
            new() { DoorsOnly = true },
            MovementOptions.Player with { Body = null, WalkableSlope = false, Vertical = false, Footing = false, EdgeSlide = false },
        ];
        int compared = 0;
        for (int n = 0; n < 3000; n++)
        {
            var local = new Vector2((float)(random.NextDouble() * 110), 30 + (float)(random.NextDouble() * 160));
            var pos = origin + new Vector3(local, 80 + (float)(random.NextDouble() * 80));
            double angle = random.NextDouble() * 2 * Math.PI, length = random.NextDouble() * 0.47; // within one sweep step
            var delta = new Vector3((float)(Math.Cos(angle) * length), (float)(Math.Sin(angle) * length), 0);
            float step = (float)(random.NextDouble() * 2);
            MovementOptions point = configurations[n % configurations.Length];
            ResolveResult without = engine.Resolve(pos, 0xA9B40000u, delta, step, point);
            ResolveResult with = engine.Resolve(pos, 0xA9B40000u, delta, step, point with { Body = MoverBody.Player });
            with.Should().Be(without, $"case {n}: {pos} moving {delta}, step {step}, {point}");
            compared++;
        }

        compared.Should().Be(3000);
    }

    [Theory]
    [InlineData("centred")]
    [InlineData("global")]
    public void Resolve_ThreeDimensionalEffectsWithoutABody_ChangeNothing(string frame)
    {
        // Vertical motion, footing and edge slide need a body: without one they are ignored, bit for bit, wherever the mover
        // is: in the air over the cellars' floor openings, on stairs, on the terrain, with a Z in the delta.
        PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs(frame);
        Vector3 origin = engine.GetLandblockOrigin(TestData.Holtburg);
        uint[] cells = [.. HoltburgCells.Fixtures.Keys, 0xA9B40000u];
        MovementOptions without = MovementOptions.Player with { Body = null, Vertical = false, Footing = false, EdgeSlide = false };
        MovementOptions ignored = MovementOptions.Player with { Body = null };
        var random = new Random(19);
        for (int n = 0; n < 3000; n++)
        {
            var pos = origin + new Vector3(133f + (float)(random.NextDouble() * 30), -1f + (float)(random.NextDouble() * 15), 89f + (float)(random.NextDouble() * 8));
            uint cell = cells[random.Next(cells.Length)];
            var delta = new Vector3((float)(random.NextDouble() - 0.5), (float)(random.NextDouble() - 0.5), (float)((random.NextDouble() * 2) - 1));
            ResolveResult expected = engine.Resolve(pos, cell, delta, 0.6f, without);
            engine.Resolve(pos, cell, delta, 0.6f, ignored).Should().Be(expected, $"case {n}: {pos} in 0x{cell:X8} moving {delta}");
        }
    }
}
