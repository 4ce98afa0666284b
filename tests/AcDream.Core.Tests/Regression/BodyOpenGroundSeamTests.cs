using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Testing;
using Xunit.Abstractions;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Regression;

/// <summary>
/// The body's open-ground shortcut beside a seam: a neighbour's building cell whose walls reach across the
/// seam into the box the body sweeps is met by the shortcut's test as by the plan, though the mover's own
/// landblock lists nothing there.
/// </summary>
[Trait("Mutation", "WallSet")]
[Trait("Mutation", "BodySweep")]
public class BodyOpenGroundSeamTests(ITestOutputHelper output)
{
    private const float GroundZ = 94f;

    [Theory]
    [InlineData("global")]
    [InlineData("centred")]
    public void A_neighbours_wall_across_the_seam_stops_the_body_as_its_plan_does(string frame)
    {
        const uint east = 0xAAB4FFFFu;
        PhysicsEngine engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, FlatTerrain(GroundZ), []);

        // The east neighbour's building cell: a wall across y = 100.5 from 0.8 m west of the seam to 0.5 m
        // east of it (the neighbour's frame), 4 m high, with no floor, and a door to the outdoors 3 m east.
        CellSurface cell = new CellBuilder(0xAAB40100u, new Vector3(0f, 100f, GroundZ))
            .Physics(Wall(-0.8f, 0.5f, 0.5f, 0.5f, 0f, 4f))
            .Portal(0xFFFF, new Vector3(3.5f, 1f, 1f), new(3f, 0.5f, 0f), new(4f, 0.5f, 0f), new(4f, 0.5f, 2f), new(3f, 0.5f, 2f)).Build();
        engine.AddLandblock(east, FlatTerrain(GroundZ, east), [cell]);

        var options = new MovementOptions { Body = MoverBody.Player };
        Vector3 origin = engine.GetLandblockOrigin(Holtburg);

        // 0.5 m west of the seam, moving 1 m north into the wall: the swept box (x 191.5 ± about 0.48 m)
        // stays west of the seam, where the neighbour's wall reaches back over it.
        Vector3 start = origin + new Vector3(191.5f, 100f, GroundZ);
        var move = new Vector2(0f, 1f);
        ResolveResult answer = engine.Resolve(start, 0xA9B40000u, new Vector3(move, 0f), 0.6f, in options);
        ResolveResult plan = engine.ResolvePlanned(start, 0xA9B40000u, move, 0.6f, in options);
        bool open = engine.IsOpenGround(start, 0xA9B40000u, move, MoverBody.Player);
        output.WriteLine($"{frame}: shortcut {open}; Resolve {answer.Outcome} at {answer.Position - origin:R}; plan {plan.Outcome} at {plan.Position - origin:R}");

        plan.Outcome.Should().NotBe(ResolveOutcome.Moved, "the plan meets the neighbour's wall");
        answer.Should().Be(plan);
        open.Should().BeFalse("the neighbour's wall reaches into the box the body sweeps");
    }
}
