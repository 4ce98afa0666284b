using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using FluentAssertions;
using Xunit;

namespace AcDream.Core.Tests.Regression;

/// <summary>
/// Defect A: a body overlapping a wall (by less than its radius) is stopped only moving into it; the step-up
/// ceiling check no longer stops it for an overlap it started with. Defect B: a mover just below a ceiling
/// opening whose move ends over the floor above (within the step) climbs out through the opening.
/// </summary>
[Trait("Mutation", "ObjectQueries")]
[Trait("Mutation", "WallSet")]
[Trait("Mutation", "BodySweep")]
[Trait("Mutation", "PortalTraversal")]
public class StairOverlapTests
{
    private static PhysicsEngine Engine(string frame) => RealObjects.HoltburgWithCellarStairs(frame);

    private static MovementOptions Short => MovementOptions.Player with { Body = new MoverBody(0.48f, 1.2f) };

    [Theory]
    [InlineData("centred", 0xA9B40174u)]
    [InlineData("centred", 0xA9B40175u)]
    [InlineData("global", 0xA9B40174u)]
    [InlineData("global", 0xA9B40175u)]
    public void A_body_3mm_into_the_shaft_wall_moves_along_and_away_from_it(string frame, uint cell)
    {
        PhysicsEngine e = Engine(frame);
        Vector3 p = e.ToWorld(TestData.Holtburg, new Vector3(153.406f, 9.754f, 93.3207f));
        foreach (Vector3 d in new[] { new Vector3(0, 0.1f, 0), new Vector3(0, -0.1f, 0), new Vector3(0.1f, 0, 0), new Vector3(0.1f, 0.1f, 0) })
        {
            ResolveResult r = e.Resolve(p, cell, d, 0.6f, Short);
            r.IsRefused.Should().BeFalse($"{frame} 0x{cell:X8} by {d}: {r}");
            (e.ToLandblockLocal(TestData.Holtburg, r.Position).X - 152.929f).Should().BeGreaterThanOrEqualTo(0.476f, $"never deeper: {r}");
        }

        e.Resolve(p, cell, new Vector3(-0.1f, 0, 0), 0.6f, Short).Outcome.Should().Be(frame == "global" ? ResolveOutcome.Slid : ResolveOutcome.Wall, "into the wall");
    }

    [Theory]
    [InlineData("centred", 0.40f)]
    [InlineData("centred", 0.45f)]
    [InlineData("centred", 0.52f)]
    [InlineData("global", 0.40f)]
    [InlineData("global", 0.52f)]
    public void Run_steps_up_building_Bs_stair_climb_out_into_the_room(string frame, float length)
    {
        PhysicsEngine e = Engine(frame);
        var r = new ResolveResult(e.ToWorld(TestData.Holtburg, new Vector3(153.5f, 9.754f, 93.3207f)), 0xA9B40174, true);
        for (int i = 0; i < 8; i++)
        {
            r = e.Resolve(r.Position, r.CellId, new Vector3(0, length, 0), 0.6f, Short);
        }

        r.CellId.Should().Be(0xA9B40171u, $"{r}");
        e.ToLandblockLocal(TestData.Holtburg, r.Position).Z.Should().BeApproximately(94f, 1e-4f);
    }

    [Fact]
    public void From_2cm_below_the_opening_a_move_ending_over_the_room_floor_lands_on_it()
    {
        PhysicsEngine e = Engine("centred");
        foreach (MovementOptions o in new[] { Short, Short with { Body = null }, Short with { Body = null, SweepStepLength = null } })
        {
            ResolveResult r = e.Resolve(new Vector3(153.5f, 10.12403f, 93.61671f), 0xA9B40174, new Vector3(0, 0.4f, 0), 0.6f, o);
            r.Outcome.Should().Be(ResolveOutcome.Moved, $"{r}");
            (r.CellId, r.Position.Z).Should().Be((0xA9B40171u, 94f));
        }
    }
}
