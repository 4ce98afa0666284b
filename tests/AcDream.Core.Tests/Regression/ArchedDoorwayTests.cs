using System.Numerics;
using AcDream.Core.Physics;
using FluentAssertions;
using Xunit;

namespace AcDream.Core.Tests.Regression;

/// <summary>
/// The cottage's north doorway 0x014F is an arch (its portal a seven-sided polygon, 1.5 m high at its crown, 0.9 m at
/// its shoulders). The wall polygons over its shoulders lie in the portal's plane with their centres inside its bounding
/// rectangle, and were once left out as the doorway's cover: a ray over a shoulder passed through the wall.
/// </summary>
[Trait("Mutation", "WallSet")]
[Trait("Mutation", "BodySweep")]
[Trait("Mutation", "PortalTraversal")]
public class ArchedDoorwayTests
{
    [Theory]
    [InlineData("centred")]
    [InlineData("global")]
    public void A_ray_over_an_arched_doorways_shoulder_meets_the_wall_over_it(string frame)
    {
        PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs(frame);
        Vector3 o = engine.GetLandblockOrigin(TestData.Holtburg);
        var from = new Vector3(138.09727f, 18.080381f, 95f);
        var to = new Vector3(137.52638f, 20.481956f, 98.14746f);

        CastHit hit = engine.Cast(o + from, 0xA9B40141u, o + to, new CastOptions(0f));

        // Where the line crosses the doorway's plane y = 18.9: x 137.902, z 96.074, over the arch's edge from
        // (137.3, 95.75) to (138.35, 96.2), which is at z 96.008 there.
        hit.Hit.Should().BeTrue($"{frame}: {hit}");
        hit.Kind.Should().Be(SurfaceKind.CellWall, $"{frame}: {hit}");
        hit.Id.Should().Be(0xA9B40141u, $"{frame}: {hit}");
        hit.CellId.Should().Be(0xA9B40141u, $"{frame}: {hit}");
        float xy = frame == "global" ? 4e-3f : 1e-3f; // world floats 34 km out are 4 mm apart
        (hit.Point - o).Y.Should().BeApproximately(18.9f, xy, $"{frame}: {hit}");
        (hit.Point - o).Z.Should().BeApproximately(96.074f, 2e-3f, $"{frame}: {hit}");
    }

    [Theory]
    [InlineData("centred")]
    [InlineData("global")]
    public void A_ray_through_the_arch_under_its_edge_passes_into_the_doorway_cell(string frame)
    {
        PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs(frame);
        Vector3 o = engine.GetLandblockOrigin(TestData.Holtburg);

        // Level through the arch at 95.9 m, 0.45 m inside its left shoulder: under its edge, through the opening.
        CastHit hit = engine.Cast(o + new Vector3(138.2f, 18.0f, 95.9f), 0xA9B40141u, o + new Vector3(138.2f, 19.2f, 95.9f), new CastOptions(0f));

        hit.Hit.Should().BeFalse($"{frame}: {hit}");
        hit.CellId.Should().Be(0xA9B4014Fu, $"{frame}: {hit}");
    }
}
