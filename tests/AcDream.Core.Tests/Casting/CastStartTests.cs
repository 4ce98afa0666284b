using System.Numerics;
using AcDream.Core.Physics;
using FluentAssertions;
using Xunit;

namespace AcDream.Core.Tests.Casting;

/// <summary>
/// Where a cast starts: within its radius of a polygon's edge or of the spec's bilinear ground, on a landblock's seam next
/// to land not loaded, and from another cast's rounded answer in the global frame (casts chained, as the chase camera's
/// slide is). Each was once answered wrongly.
/// </summary>
[Trait("Mutation", "SweptSphere")]
public class CastStartTests
{
    public static TheoryData<string> Frames() => new() { "centred", "global" };

    private static PhysicsEngine Engine(string frame) => frame == "global" ? new PhysicsEngine() : new PhysicsEngine(TestData.Holtburg);

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_sphere_gliding_over_the_ground_across_the_terrain_triangles_edges_meets_nothing(string frame)
    {
        // 0.1 m over flat ground, 0.1 m from a terrain cell's diagonal and its edges, moving level across them: the
        // ground's edges are within the radius at the start, but the sphere moves along the ground, not into it.
        PhysicsEngine engine = Engine(frame);
        engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(94f), []);
        Vector3 o = engine.GetLandblockOrigin(TestData.Holtburg);
        foreach ((Vector3 from, Vector3 to) in new[]
        {
            (new Vector3(36.1f, 36.0f, 94.1f), new Vector3(30f, 42f, 94.1f)), // across the diagonal of cell (1, 1)
            (new Vector3(48.1f, 40f, 94.1f), new Vector3(44f, 40f, 94.1f)),   // across the edge x = 48
            (new Vector3(48.1f, 48.1f, 94.1f), new Vector3(44f, 44f, 94.1f)), // across the corner (48, 48)
        })
        {
            CastHit hit = engine.Cast(o + from, 0, o + to, new CastOptions(0.3f));
            hit.Hit.Should().BeFalse($"{frame}: {from} → {to}: {hit}");
        }

        // Moving down into the ground from the same starts, it is met at once.
        CastHit down = engine.Cast(o + new Vector3(36.1f, 36.0f, 94.1f), 0, o + new Vector3(36.1f, 36.0f, 93f), new CastOptions(0.3f));
        down.Hit.Should().BeTrue($"{frame}: {down}");
        down.Fraction.Should().Be(0f, $"{frame}: {down}");
        down.Normal.Should().Be(Vector3.UnitZ, $"{frame}: {down}");
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_sphere_sliding_along_a_wall_past_its_end_meets_nothing_and_one_moving_into_it_is_met_at_once(string frame)
    {
        // The cottage's main room 0xA9B40143: its east wall at x = 142.1; 0.2 m from it, moving north along it.
        PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs(frame);
        Vector3 o = engine.GetLandblockOrigin(TestData.Holtburg);
        CastHit along = engine.Cast(o + new Vector3(141.9f, 8f, 95f), 0xA9B40143u, o + new Vector3(141.9f, 12.5f, 95f), new CastOptions(0.3f));
        CastHit into = engine.Cast(o + new Vector3(141.9f, 8f, 95f), 0xA9B40143u, o + new Vector3(143f, 8f, 95f), new CastOptions(0.3f));

        along.Hit.Should().BeFalse($"{frame}: {along}");
        into.Hit.Should().BeTrue($"{frame}: {into}");
        into.Fraction.Should().Be(0f, $"{frame}: {into}");
        into.Kind.Should().Be(SurfaceKind.CellWall, $"{frame}: {into}");
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void On_the_specs_bilinear_ground_a_sphere_within_it_is_met_moving_down_and_a_ray_leaving_it_is_free(string frame)
    {
        byte[] heights = TestData.Heights((x, y) => 10 + (x * 3) + (y * 2) + ((x * y) % 5));
        var terrain = new TerrainSurface(heights, TestData.LinearTable());
        PhysicsEngine engine = Engine(frame);
        engine.AddLandblock(TestData.Holtburg, terrain, []);
        Vector3 o = engine.GetLandblockOrigin(TestData.Holtburg);
        var feet = new Vector3(50.5f, 61.25f, terrain.SampleZ(50.5f, 61.25f));

        CastHit down = engine.Cast(o + feet + new Vector3(0, 0, 0.1f), 0, o + feet + new Vector3(2f, 1f, -1f), new CastOptions(0.3f));
        CastHit up = engine.Cast(o + feet, 0, o + feet + new Vector3(3f, 2f, 1.5f), new CastOptions(0f));

        down.Hit.Should().BeTrue($"{frame}: {down}");
        down.Fraction.Should().Be(0f, $"{frame}: {down}");
        down.Kind.Should().Be(SurfaceKind.Terrain, $"{frame}: {down}");
        up.Hit.Should().BeFalse($"{frame}: {up}");
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_cast_from_a_landblocks_east_seam_westwards_is_not_stopped_by_the_unloaded_land_east_of_it(string frame)
    {
        PhysicsEngine engine = Engine(frame);
        engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(94f), []); // 0xAAB4, east of it, is not loaded
        Vector3 o = engine.GetLandblockOrigin(TestData.Holtburg);

        // On the seam x = 192 in the east column's outdoor cell 0x3D of 0xA9B4 (the id names the landblock; 0 would pick the
        // one under the position, east of the seam).
        CastHit west = engine.Cast(o + new Vector3(192f, 100f, 95f), 0xA9B4003Du, o + new Vector3(180f, 100f, 94.5f), new CastOptions(0.3f));
        CastHit east = engine.Cast(o + new Vector3(192f, 100f, 95f), 0xA9B4003Du, o + new Vector3(200f, 100f, 95f), new CastOptions(0f));

        west.Hit.Should().BeFalse($"{frame}: {west}");
        west.CellId.Should().Be(0xA9B4003Du, $"{frame}: {west}");
        east.Hit.Should().BeTrue($"{frame}: {east}");
        east.Kind.Should().Be(SurfaceKind.None, $"{frame}: the land east is not loaded: {east}");
        east.Fraction.Should().Be(0f, $"{frame}: {east}");
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_cast_from_another_casts_rounded_answer_in_a_doorway_goes_on_through_the_doorway(string frame)
    {
        // Into the west door cell 0xA9B40145 to 1.5 mm past its outdoor portal (x = 136.3); in the global frame the answer
        // is rounded to world floats 4 mm apart, which may put it back outside the portal while naming the door cell. A cast
        // from that answer out and down must still leave by the door and meet the ground outside.
        PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs(frame);
        Vector3 o = engine.GetLandblockOrigin(TestData.Holtburg);
        foreach (float past in new[] { 0.0005f, 0.0015f, 0.003f })
        {
            CastHit first = engine.Cast(o + new Vector3(130f, 5.15f, 95f), 0, o + new Vector3(136.3f + past, 5.15f, 95f), new CastOptions(0f));
            first.Hit.Should().BeFalse($"{frame}, {past}: {first}");
            first.CellId.Should().Be(0xA9B40145u, $"{frame}, {past}: {first}");

            CastHit second = engine.Cast(first.Position, first.CellId, o + new Vector3(132f, 5.15f, 93f), new CastOptions(0f));
            second.Hit.Should().BeTrue($"{frame}, {past}: from {first.Position - o}: {second}");
            second.Kind.Should().Be(SurfaceKind.Terrain, $"{frame}, {past}: from {first.Position - o}: {second}");
            second.CellId.Should().Be(0xA9B40029u, $"{frame}, {past}: {second}");
            (second.Point - o).Z.Should().BeApproximately(94f, 1e-3f, $"{frame}, {past}: {second}");
        }
    }
}
