using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.Core.Physics;
using AcDream.Testing;
using Xunit.Abstractions;
using static AcDream.Testing.CastReference;

namespace AcDream.Core.Tests.Casting;

/// <summary>
/// Casts that meet an object standing in a neighbouring cell where it rises out of that cell: building B's cellar stair
/// 0x01FFF174 stands in the cellar 0xA9B40174 and its top landing (a ramp from z 93.4 at y 9.853 to 93.8 at y 10.353)
/// rises 0.164 m above the floor opening (z 93.636) into the shaft 0xA9B40175. A cast in the shaft that stays above the
/// opening meets the landing where the reference does, in both world frames.
/// </summary>
public class CastNeighbourObjectTests(ITestOutputHelper output)
{
    private const uint Shaft = 0xA9B40175;

    /// <summary>The landing's plane: its Z at a landblock-local Y (the ramp's own plane: 0.8 m up per metre north).</summary>
    private static double LandingZ(double y) => 93.4 + ((y - 9.853149) * 0.8);

    [Theory]
    [InlineData("centred", 154, 10.33, 93.95, 154, 10.17, 93.65, 0.97976)]
    [InlineData("global", 154, 10.33, 93.95, 154, 10.17, 93.65, 0.97976)]
    [InlineData("centred", 153.5, 10.34, 93.97, 153.5, 10.25, 93.69, 0.867886)]
    [InlineData("global", 153.5, 10.34, 93.97, 153.5, 10.25, 93.69, 0.867886)]
    public void A_ray_in_the_shaft_meets_the_cellar_stairs_landing_above_the_opening(string frame, double x0, double y0, double z0, double x1, double y1, double z1, double near)
    {
        // Its path stays above the opening (its lowest point 93.65 m > 93.636 m): it never passes into the cellar.
        CastScene scene = CastWorlds.Holtburg(frame, terrain: false, shells: false);
        var worst = new Deviations(frame);
        Vector3 from = scene.World(x0, y0, z0), to = scene.World(x1, y1, z1);
        CastHit hit = scene.Check(from, Shaft, to, 0f, worst, "a ray down the shaft onto the landing");
        output.WriteLine($"[{frame}] {hit}; {worst}");
        (hit.Kind, hit.Id).Should().Be((SurfaceKind.ObjectFloor, ObjectPlacements.BuildingBCellarStair));
        if (frame == "centred")
        {
            hit.Fraction.Should().BeApproximately((float)near, 1e-5f); // (the global frame rounds the ends to 4 mm: another segment)
        }
    }

    [Theory]
    [MemberData(nameof(CastWorlds.Frames), MemberType = typeof(CastWorlds))]
    public void Rays_and_spheres_in_the_shaft_meet_the_landing_where_the_reference_does(string frame)
    {
        // Starts in the shaft (x 153.0–154.85, y 6.5–9.8, z 93.66–93.98, clear of its walls by the radius), aimed at points
        // of the landing above the opening and half as far again.
        CastScene scene = CastWorlds.Holtburg(frame, terrain: false, shells: false);
        var random = new Random(77);
        var worst = new Deviations(frame);
        int landing = 0, casts = 0;
        foreach (float r in new[] { 0f, 0.02f, 0.05f, 0.1f })
        {
            for (int n = 0; n < 60; n++)
            {
                double y = 10.16 + (random.NextDouble() * 0.19);
                var target = new V3(153.1 + (random.NextDouble() * 1.65), y, LandingZ(y));
                var start = new V3(153.0 + (random.NextDouble() * 1.85), 6.5 + (random.NextDouble() * 3.3), 93.66 + r + (random.NextDouble() * (0.32 - (2 * r))));
                if (scene.Clearance(start) < r + 0.005)
                {
                    continue;
                }

                Vector3 from = scene.World(start), to = scene.World(start + ((target + new V3(0, 0, r) - start) * 1.5));
                CastHit hit = scene.Engine.Cast(from, Shaft, to, new CastOptions(r));
                scene.Tally(hit, scene.Expected(from, to, r), from, to, r, worst, $"r {r}, cast {n} at {target}");
                landing += hit.Id == ObjectPlacements.BuildingBCellarStair ? 1 : 0;
                casts++;
            }
        }

        output.WriteLine($"{worst}; {landing} of {casts} met the landing");
        worst.Failures.Should().BeEmpty(worst.FailureReport());
        landing.Should().BeGreaterThan(casts / 2);
    }
}
