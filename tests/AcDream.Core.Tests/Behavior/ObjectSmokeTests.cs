using System.Numerics;
using AcDream.Core.Physics;
using FluentAssertions;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

/// <summary>First checks of objects on the real data: the cottage's shell and the outdoor staircase.</summary>
[Trait("Mutation", "ObjectQueries")]
public class ObjectSmokeTests
{
    private const float Step = 0.6f;

    private static PhysicsEngine Holtburg()
    {
        var engine = new PhysicsEngine(TestData.Holtburg);
        engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(94f), HoltburgCells.Surfaces(), RealObjects.HoltburgBuildings());
        return engine;
    }

    [Fact]
    public void The_shell_stops_a_walk_into_its_wall_from_outside()
    {
        PhysicsEngine engine = Holtburg();
        // East of the main block's wall x = 142.5 (landblock), walking west into it.
        ResolveResult r = engine.Resolve(new Vector3(142.8f, 12f, 94f), 0xA9B40000, new Vector3(-0.5f, 0f, 0f), Step);
        r.Outcome.Should().Be(ResolveOutcome.OuterWall, $"result {r}");
        r.Position.X.Should().Be(142.8f);
    }

    [Fact]
    public void The_west_door_still_enters_0145()
    {
        PhysicsEngine engine = Holtburg();
        ResolveResult at = new(new Vector3(135.6f, 5.15f, 94f), 0xA9B40000, true);
        for (int i = 0; i < 20 && at.CellId != 0xA9B40145; i++)
        {
            at = engine.Resolve(at.Position, at.CellId, new Vector3(0.1f, 0f, 0f), Step);
        }

        at.CellId.Should().Be(0xA9B40145u, $"ended {at}");
    }

    [Fact]
    public void The_staircase_is_climbed_and_descended()
    {
        var engine = new PhysicsEngine(0xF682FFFF);
        engine.AddLandblock(0xF682FFFF, TestData.FlatTerrain(58.815f, 0xF682FFFF), [], RealObjects.Staircase());
        var at = new ResolveResult(new Vector3(132f, 73.5f, 58.815f), 0xF6820000, true);
        for (int i = 0; i < 54; i++)
        {
            at = engine.Resolve(at.Position, at.CellId, new Vector3(0f, 0.1f, 0f), Step);
        }

        // y 78.9: 0.095 m before the top edge (y 78.995, z 62.215) of the 38.66° ramp.
        at.Position.Z.Should().BeApproximately(62.215f - (0.095f * 0.8f), 0.002f, $"near the top: {at}");
        for (int i = 0; i < 54; i++)
        {
            at = engine.Resolve(at.Position, at.CellId, new Vector3(0f, -0.1f, 0f), Step);
        }

        at.Position.Z.Should().Be(58.815f, $"back on the ground: {at}");
    }
}
