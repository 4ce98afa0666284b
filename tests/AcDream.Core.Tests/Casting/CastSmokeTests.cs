using System.Numerics;
using AcDream.Core.Physics;
using FluentAssertions;
using Xunit;

namespace AcDream.Core.Tests.Casting;

[Trait("Mutation", "SweptSphere")]
public class CastSmokeTests
{
    [Fact]
    public void A_ray_down_meets_flat_terrain_and_a_sphere_stops_its_radius_above()
    {
        var engine = new PhysicsEngine(TestData.Holtburg);
        engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(94f), []);
        CastHit ray = engine.Cast(new Vector3(50, 50, 100), 0, new Vector3(50, 50, 90), new CastOptions(0f));
        ray.Hit.Should().BeTrue();
        ray.Kind.Should().Be(SurfaceKind.Terrain);
        ray.Position.Z.Should().BeApproximately(94f, 1e-4f, $"{ray}");
        ray.Fraction.Should().BeApproximately(0.6f, 1e-6f);
        ray.Normal.Should().Be(new Vector3(0, 0, 1));

        CastHit sphere = engine.Cast(new Vector3(50, 50, 100), 0, new Vector3(60, 50, 90), new CastOptions(0.3f));
        sphere.Hit.Should().BeTrue();
        sphere.Position.Z.Should().BeApproximately(94.3f, 1e-4f, $"{sphere}");
        sphere.Point.Z.Should().BeApproximately(94f, 1e-4f, $"{sphere}");
    }

    [Fact]
    public void A_ray_from_the_cellar_to_the_yard_is_blocked()
    {
        foreach (string frame in new[] { "global", "centred" })
        {
            PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs(frame);
            CellSurface cellar = HoltburgCells.Surface(0xA9B40147);
            Vector3 origin = engine.GetLandblockOrigin(TestData.Holtburg);
            var floors = cellar.GetFloorTriangles();
            Vector3 c = (floors[0].A + floors[0].B + floors[0].C) / 3f;
            Vector3 from = origin + c + new Vector3(0, 0, 1f);
            Vector3 to = origin + new Vector3(100, 100, 95);
            CastHit hit = engine.Cast(from, 0xA9B40147, to, new CastOptions(0f));
            hit.Hit.Should().BeTrue($"{frame}: {hit}");
            hit.Fraction.Should().BeLessThan(0.2f, $"{frame}: {hit}");
        }
    }

    [Fact]
    public void A_cast_starting_on_the_ground_or_a_floor_and_moving_up_meets_nothing_there()
    {
        foreach (string frame in new[] { "global", "centred" })
        {
            PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs(frame);
            Vector3 o = engine.GetLandblockOrigin(TestData.Holtburg);
            foreach (float radius in new[] { 0f, 0.3f })
            {
                CastHit terrain = engine.Cast(o + new Vector3(120, 0, 94), 0, o + new Vector3(120, 0, 95.5f), new CastOptions(radius));
                CastHit floor = engine.Cast(o + new Vector3(139, 10, 94), 0xA9B40143u, o + new Vector3(139, 10, 95.5f), new CastOptions(radius));
                terrain.Hit.Should().BeFalse($"{frame}, r {radius}: {terrain}");
                floor.Hit.Should().BeFalse($"{frame}, r {radius}: {floor}");
                floor.CellId.Should().Be(0xA9B40143u, $"{frame}, r {radius}: {floor}");
            }
        }
    }
}
