using AcDream.Core.Physics;
using AcDream.Testing;
using Xunit.Abstractions;
using static AcDream.Testing.CastReference;

namespace AcDream.Core.Tests.Casting;

/// <summary>
/// The reference itself against answers worked out by hand (closed form): a ray and spheres onto a face, past an edge
/// and a corner, onto a cylinder's side, cap and rim, grazing a face at 1e-3 rad, missing by a millimetre; and its
/// terrain split against the game's rule as the engine holds it.
/// </summary>
[Trait("Mutation", "SweptSphere")]
public class CastReferenceTests(ITestOutputHelper output)
{
    private const double Exact = 1e-9;

    private static Polygon Square(double x, double y0, double y1, double z0, double z1) =>
        new([new V3(x, y0, z0), new V3(x, y1, z0), new V3(x, y1, z1), new V3(x, y0, z1)], SurfaceKind.CellWall, 1, "wall x=" + x);

    [Fact]
    public void A_ray_and_spheres_meet_a_face_where_the_centre_is_a_radius_from_its_plane()
    {
        var reference = new CastReference([Square(5, -2, 2, -2, 2)]);
        foreach (double r in new[] { 0.0, 0.05, 0.3, 1.0 })
        {
            Hit hit = reference.Cast(new V3(0, 0.5, 0.25), new V3(10, 0.5, 0.25), r)!;
            hit.T.Should().BeApproximately((5 - r) / 10, Exact / 10, $"r {r}: {hit}");
            (hit.Point - new V3(5, 0.5, 0.25)).Length.Should().BeLessThan(Exact, $"{hit}");
            hit.Normals.Should().ContainSingle().Which.Should().Be(new V3(-1, 0, 0), $"{hit}");

            Hit back = reference.Cast(new V3(10, 0.5, 0.25), new V3(0, 0.5, 0.25), r)!;
            back.T.Should().BeApproximately((5 - r) / 10, Exact / 10, $"from the other side, r {r}: {back}");
            back.Normals.Should().ContainSingle().Which.Should().Be(new V3(1, 0, 0), $"{back}");
        }
    }

    [Fact]
    public void A_sphere_past_an_edge_meets_it_where_the_edge_is_a_radius_away_and_misses_by_a_millimetre()
    {
        // The wall x = 0, y −5..0: its edge is the line x = y = 0. A sphere moving along −x at y = 0.1 meets the edge when
        // x² + 0.1² = r²; at y = r + 0.001 it passes.
        var reference = new CastReference([new Polygon([new V3(0, -5, -5), new V3(0, 0, -5), new V3(0, 0, 5), new V3(0, -5, 5)], SurfaceKind.CellWall, 1, "wall")]);
        const double r = 0.3;
        Hit hit = reference.Cast(new V3(2, 0.1, 0), new V3(-2, 0.1, 0), r)!;
        hit.T.Should().BeApproximately((2 - Math.Sqrt((r * r) - 0.01)) / 4, Exact / 4, $"{hit}");
        (hit.Point - new V3(0, 0, 0)).Length.Should().BeLessThan(Exact, $"{hit}");
        reference.Cast(new V3(2, r + 0.001, 0), new V3(-2, r + 0.001, 0), r).Should().BeNull();

        // A corner: the sphere moving down the line through (0.1, 0.1) above the wall's top corner (0, 0, 5).
        Hit corner = reference.Cast(new V3(0.1, 0.1, 8), new V3(0.1, 0.1, 2), r)!;
        corner.T.Should().BeApproximately((8 - 5 - Math.Sqrt((r * r) - 0.02)) / 6, Exact / 6, $"{corner}");
        (corner.Point - new V3(0, 0, 5)).Length.Should().BeLessThan(Exact, $"{corner}");
    }

    [Fact]
    public void A_sphere_meets_a_cylinders_side_cap_and_rim_where_closed_form_says()
    {
        var reference = new CastReference([new CastReference.Cylinder(0, 0, 0.5, 0, 2, SurfaceKind.Mover, 1, "cylinder")]);
        const double r = 0.3;

        Hit side = reference.Cast(new V3(-4, 0.2, 1), new V3(4, 0.2, 1), r)!; // x² + 0.04 = 0.8²
        side.T.Should().BeApproximately((4 - Math.Sqrt(0.64 - 0.04)) / 8, Exact / 8, $"{side}");
        Hit ray = reference.Cast(new V3(-4, 0.2, 1), new V3(4, 0.2, 1), 0)!; // x² + 0.04 = 0.5²
        ray.T.Should().BeApproximately((4 - Math.Sqrt(0.25 - 0.04)) / 8, Exact / 8, $"{ray}");

        Hit cap = reference.Cast(new V3(0.3, 0.1, 5), new V3(0.3, 0.1, 0), r)!;
        cap.T.Should().BeApproximately((5 - 2.3) / 5, Exact / 5, $"{cap}");
        (cap.Normals.Should().ContainSingle().Which - new V3(0, 0, 1)).Length.Should().BeLessThan(1e-9);

        // Straight down at 0.6 m from the axis: the rim (radius 0.5 at z 2) when (0.6 − 0.5)² + (z − 2)² = r².
        Hit rim = reference.Cast(new V3(0.6, 0, 5), new V3(0.6, 0, 0), r)!;
        rim.T.Should().BeApproximately((5 - 2 - Math.Sqrt((r * r) - 0.01)) / 5, Exact / 5, $"{rim}");
        (rim.Point - new V3(0.5, 0, 2)).Length.Should().BeLessThan(1e-8, $"{rim}");

        reference.Cast(new V3(0.5 + r + 0.001, 0, 5), new V3(0.5 + r + 0.001, 0, -1), r).Should().BeNull("it passes the side by a millimetre");
    }

    [Theory]
    [InlineData(0.0)]
    [InlineData(0.3)]
    public void A_cast_grazing_a_face_at_a_thousandth_of_a_radian_is_found_to_nanometres(double r)
    {
        // The floor z = 0 (x, y −1000..1000); the centre starts 0.5 + r above it and descends at 1e-3 rad.
        var reference = new CastReference([new Polygon([new V3(-1000, -1000, 0), new V3(1000, -1000, 0), new V3(1000, 1000, 0), new V3(-1000, 1000, 0)], SurfaceKind.CellFloor, 1, "floor")]);
        double angle = 1e-3, length = 0.9 / Math.Sin(angle);
        var from = new V3(-10, 0, 0.5 + r);
        V3 to = from + new V3(Math.Cos(angle) * length, 0, -Math.Sin(angle) * length);
        Hit hit = reference.Cast(from, to, r)!;
        double expected = 0.5 / Math.Sin(angle) / length;
        output.WriteLine($"r {r}: t {hit.T:R}, expected {expected:R}, travel difference {Math.Abs(hit.T - expected) * length:E2} m");
        (Math.Abs(hit.T - expected) * length).Should().BeLessThan(2e-9, $"{hit}");
    }

    [Fact]
    public void The_terrain_split_is_the_games_rule_as_the_engine_holds_it()
    {
        var random = new Random(21);
        for (int n = 0; n < 20_000; n++)
        {
            uint gx = (uint)random.Next(0, 2040), gy = (uint)random.Next(0, 2040);
            SplitsSwToNe(gx, gy).Should().Be(TerrainSurface.IsSplitSwToNe(gx, gy), $"global cell ({gx}, {gy})");
        }
    }

    [Theory]
    [MemberData(nameof(CastWorlds.Frames), MemberType = typeof(CastWorlds))]
    public void The_reference_terrain_is_the_engines_ground(string frame)
    {
        // Straight down onto the hills: the reference's contact Z is the engine's sampled ground (its own test of the
        // game's triangles), within float rounding.
        (CastScene scene, TerrainSurface terrain) = CastWorlds.Hills(3, frame);
        var random = new Random(4);
        for (int n = 0; n < 400; n++)
        {
            double x = (float)(random.NextDouble() * 192), y = (float)(random.NextDouble() * 192); // floats: the engine's sample is at a float point
            Hit hit = scene.Reference.Cast(new V3(x, y, 1000), new V3(x, y, 400), 0)!;
            hit.Point.Z.Should().BeApproximately(terrain.SampleZ((float)x, (float)y), 1e-4, $"({x}, {y}): {hit}");
        }
    }
}
