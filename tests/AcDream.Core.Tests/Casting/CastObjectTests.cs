using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using AcDream.Core.Tests.Moving;
using AcDream.Core.Tests.Robustness;
using AcDream.Testing;
using Xunit.Abstractions;
using static AcDream.Testing.CastReference;

namespace AcDream.Core.Tests.Casting;

/// <summary>
/// Casts at objects against <see cref="CastReference"/>, in both world frames (in the global frame positions are
/// compared in landblock-local terms within their float rounding, and the travel to the contact exactly): the cottage's
/// shell and building B's walls from the yard, the cellar stair from the cellar, an object's cylinder (a tree's trunk:
/// its side, its top and its rim) and a creature's (a mover), each passed at its radius less or more 1 cm and 1 mm.
/// </summary>
public class CastObjectTests(ITestOutputHelper output)
{
    private static readonly float[] Radii = [0f, 0.3f, 0.1f, 0.6f];

    [Theory]
    [MemberData(nameof(CastWorlds.Frames), MemberType = typeof(CastWorlds))]
    public void Rays_and_spheres_from_the_yard_meet_the_shells_and_walls_of_the_buildings_where_the_reference_does(string frame)
    {
        // From 1–15 m outside the cottage (x 130–143, y 3–20) and building B (x 152–165, y 4–16), at points of their
        // bounds. A cast whose centre passes in through a doorway goes on indoors, where the world is another: those are
        // the doorway tests' (CastCellTests, CastDoorTests), and are left out here.
        CastScene scene = CastWorlds.HoltburgOutdoors(frame);
        V3[][] doorways = [.. CastWorlds.HoltburgPortals().Where(p => p.Other == 0xFFFF).Select(p => p.Polygon)];
        (V3 Lo, V3 Hi)[] buildings = [(new V3(130, 3, 93), new V3(143, 20, 103)), (new V3(152.5, 4.3, 93), new V3(165, 16.3, 103))]; // from 1 m below ground
        var random = new Random(41);
        var worst = new Deviations(frame);
        var kinds = new Dictionary<SurfaceKind, int>();
        int inward = 0;
        for (int n = 0; n < 1200; n++)
        {
            (V3 lo, V3 hi) = buildings[n % 2];
            float r = Radii[(n / 2) % Radii.Length];
            var target = new V3(lo.X + (random.NextDouble() * (hi.X - lo.X)), lo.Y + (random.NextDouble() * (hi.Y - lo.Y)), lo.Z + (random.NextDouble() * (hi.Z - lo.Z)));
            double azimuth = random.NextDouble() * 2 * Math.PI;
            V3 centre = (lo + hi) * 0.5;
            var start = new V3(centre.X + (Math.Cos(azimuth) * (12 + (random.NextDouble() * 10))), centre.Y + (Math.Sin(azimuth) * (12 + (random.NextDouble() * 10))), 94 + r + 0.05 + (random.NextDouble() * 8));
            V3 end = start + ((target - start) * 1.3);
            if (scene.Clearance(start) < r + 0.01)
            {
                continue;
            }

            Vector3 from = scene.World(start), to = scene.World(end);
            Hit? expected = scene.Expected(from, to, r);
            V3 a = scene.Local(from), b = scene.Local(to);
            if (doorways.Any(p => CastWorlds.Crossing(p, a, b) is double t && t < (expected?.T ?? 1.0)))
            {
                inward++;
                continue;
            }

            CastHit hit = scene.Engine.Cast(from, 0, to, new CastOptions(r));
            scene.Tally(hit, expected, from, to, r, worst, $"cast {n} at {target}");
            kinds[hit.Kind] = kinds.GetValueOrDefault(hit.Kind) + 1;
        }

        output.WriteLine($"{worst}; {inward} passed in through a doorway (left to the doorway tests); met: {string.Join(", ", kinds.OrderBy(k => k.Key).Select(k => $"{k.Key} {k.Value}"))}");
        worst.Failures.Should().BeEmpty(worst.FailureReport());
        kinds.GetValueOrDefault(SurfaceKind.BuildingShell).Should().BeGreaterThan(200);
        kinds.GetValueOrDefault(SurfaceKind.CellWall).Should().BeGreaterThan(100, "building B has no shell: its cells' walls are met from outside");
        kinds.GetValueOrDefault(SurfaceKind.Terrain).Should().BeGreaterThan(20);
    }

    [Theory]
    [MemberData(nameof(CastWorlds.Frames), MemberType = typeof(CastWorlds))]
    public void Rays_and_spheres_in_the_cellar_meet_the_stair_where_the_reference_does(string frame)
    {
        // The cottage stair (x 140.5–142.1, y 5.8–8.7, its ramp from z 91 up to 94): aimed at points of it from the cellar.
        CastScene scene = CastWorlds.Holtburg(frame, terrain: false, shells: false);
        var random = new Random(42);
        var worst = new Deviations(frame);
        int stair = 0;
        for (int n = 0; n < 300; n++)
        {
            float r = Radii[n % Radii.Length] * 0.5f;
            var target = new V3(140.5 + (random.NextDouble() * 1.6), 5.8 + (random.NextDouble() * 2.9), 91 + (random.NextDouble() * 2.7));
            var start = new V3(137 + (random.NextDouble() * 3), random.NextDouble() * 11, 91.2 + (random.NextDouble() * 2.4));
            if (scene.Clearance(start) < r + 0.01 || (start.X > 140.3 && start.Y > 5.6 && start.Y < 8.9))
            {
                continue;
            }

            Vector3 from = scene.World(start), to = scene.World(start + ((target - start) * 1.5));
            CastHit hit = scene.Engine.Cast(from, ObjectPlacements.CottageCellar, to, new CastOptions(r));
            scene.Tally(hit, scene.Expected(from, to, r), from, to, r, worst, $"cast {n} at {target}");
            stair += hit.Id == ObjectPlacements.CottageCellarStair ? 1 : 0;
        }

        output.WriteLine($"{worst}; {stair} met the stair");
        worst.Failures.Should().BeEmpty(worst.FailureReport());
        stair.Should().BeGreaterThan(100);
    }

    /// <summary>One cylinder on flat ground at 50 m in landblock 0x7A3B: a tree's trunk (an object's CylSphere, radius 0.4, height 5), or a creature (a mover, 0.48 by 1.835).</summary>
    private static (CastScene Scene, V3 Axis, double Radius, double Height, SurfaceKind Kind, uint Id) Cylinder(string what, string frame)
    {
        const uint landblock = MoverSmokeTests.Landblock;
        PhysicsEngine engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(landblock);
        var axis = new V3(96.25, 95.5, 50);
        if (what == "tree")
        {
            (Setup setup, Dictionary<uint, GfxObj> parts) = ObjectKit.Tree();
            var tree = new ObjectSurface(setup, parts, ObjectKit.At(new Vector3(96.25f, 95.5f, 50f), 0.7f), 0);
            engine.AddLandblock(landblock, TestData.FlatTerrain(50f, landblock), [], [tree]);
        }
        else
        {
            engine.AddLandblock(landblock, TestData.FlatTerrain(50f, landblock), []);
            engine.Movers.Add(7, MoverKit.Human, engine.ToWorld(landblock, new Vector3(96.25f, 95.5f, 50f)), MoverSmokeTests.Outdoor, Quaternion.Identity, MoverState.Creature);
            engine.Movers.Commit();
        }

        (double radius, double height, SurfaceKind kind, uint id) = what == "tree" ? (0.4, 5.0, SurfaceKind.Cylinder, 0x02000001u) : (MoverKit.HumanRadius, MoverKit.HumanHeight, SurfaceKind.Mover, 7u);
        var shapes = new List<Shape>
        {
            new CastReference.Cylinder(axis.X, axis.Y, (float)radius, axis.Z, (float)(axis.Z + (float)height), kind, id, what), // its top a float, as stored
        };
        shapes.AddRange(CastWorlds.Terrain(CastWorlds.Flat(50f), landblock, default));
        return (new CastScene(engine, frame, landblock, shapes), axis, (float)radius, (float)height, kind, id);
    }

    public static TheoryData<string, string> Cylinders() => new()
    {
        { "tree", "centred" }, { "tree", "global" }, { "creature", "centred" }, { "creature", "global" },
    };

    [Theory]
    [MemberData(nameof(Cylinders))]
    public void Rays_and_spheres_meet_a_cylinders_side_top_and_rim_where_the_reference_does(string what, string frame)
    {
        (CastScene scene, V3 axis, double radius, double height, SurfaceKind kind, uint id) = Cylinder(what, frame);
        var random = new Random(43);
        var worst = new Deviations(frame);
        var parts = new Dictionary<string, int>();
        for (int n = 0; n < 600; n++)
        {
            float r = Radii[n % Radii.Length];
            // A point of the cylinder's surface: its side, its top, or its rim, and a path at it from outside.
            double angle = random.NextDouble() * 2 * Math.PI;
            int part = n % 3;
            double z = part == 0 ? random.NextDouble() * height : height;
            double rho = part == 1 ? random.NextDouble() * radius : radius;
            V3 point = axis + new V3(Math.Cos(angle) * rho, Math.Sin(angle) * rho, z);
            V3 outward = part == 0 ? new V3(Math.Cos(angle), Math.Sin(angle), 0) : part == 1 ? new V3(0, 0, 1) : new V3(Math.Cos(angle), Math.Sin(angle), 1) * Math.Sqrt(0.5);
            double tilt = random.NextDouble() * 1.2;
            V3 sideways = V3.Cross(outward, new V3(0.3, 0.5, 0.8));
            V3 dir = -((outward * Math.Cos(tilt)) + (sideways * (Math.Sin(tilt) / sideways.Length)));
            V3 start = point + (outward * r) - (dir * (1 + (random.NextDouble() * 4)));
            if (start.Z < 50 + r + 0.01 || scene.Clearance(start) < r + 0.01)
            {
                continue;
            }

            Vector3 from = scene.World(start), to = scene.World(point + (outward * r) + (dir * 0.5));
            CastHit hit = scene.Engine.Cast(from, 0, to, new CastOptions(r));
            scene.Tally(hit, scene.Expected(from, to, r), from, to, r, worst, $"{what} {(part == 0 ? "side" : part == 1 ? "top" : "rim")} at {point}, cast {n}");
            if (hit.Hit && hit.Kind == kind)
            {
                hit.Id.Should().Be(id);
                string name = part == 0 ? "side" : part == 1 ? "top" : "rim";
                parts[name] = parts.GetValueOrDefault(name) + 1;
            }
        }

        output.WriteLine($"{what}: {worst}; met: {string.Join(", ", parts.Select(p => $"{p.Key} {p.Value}"))}");
        worst.Failures.Should().BeEmpty(worst.FailureReport());
        parts.Values.Should().HaveCount(3).And.OnlyContain(c => c > 60);
    }

    [Theory]
    [MemberData(nameof(Cylinders))]
    public void Casts_passing_a_cylinder_within_or_beyond_their_radius_meet_it_or_pass_as_the_reference_says(string what, string frame)
    {
        // Level paths whose nearest approach to the side is the cast's radius less or more 1 cm or 1 mm (a ray's: 1 cm or
        // 1 mm inside or outside the side); and paths straight down past the rim likewise.
        (CastScene scene, V3 axis, double radius, double height, _, _) = Cylinder(what, frame);
        var random = new Random(44);
        var worst = new Deviations(frame);
        int met = 0, passed = 0;
        foreach (float r in new[] { 0f, 0.3f, 0.1f })
        {
            foreach (double by in new[] { -0.01, -0.001, 0.001, 0.01 })
            {
                for (int k = 0; k < 6; k++)
                {
                    double angle = random.NextDouble() * 2 * Math.PI;
                    var toward = new V3(Math.Cos(angle), Math.Sin(angle), 0);
                    var across = new V3(-toward.Y, toward.X, 0);
                    // Past the side, level, at mid-height.
                    V3 closest = axis + (across * (radius + r + by)) + new V3(0, 0, height / 2);
                    V3 rim = axis + new V3(0, 0, height) + (toward * (radius + r + by)); // straight down past the rim, nearest it at the top's height
                    foreach ((V3 a, V3 b) in new[] { (closest - (toward * 3), closest + (toward * 3)), (rim + new V3(0, 0, 3), rim + new V3(0, 0, -0.5)) })
                    {
                        Vector3 from = scene.World(a), to = scene.World(b);
                        CastHit hit = scene.Engine.Cast(from, 0, to, new CastOptions(r));
                        scene.Tally(hit, scene.Expected(from, to, r), from, to, r, worst, $"{what}: past at the radius {r} + {by}");
                        met += hit.Hit && hit.Kind != SurfaceKind.Terrain ? 1 : 0;
                        passed += hit.Hit && hit.Kind != SurfaceKind.Terrain ? 0 : 1;
                    }
                }
            }
        }

        output.WriteLine($"{what}: {worst}; {met} met it, {passed} passed");
        worst.Failures.Should().BeEmpty(worst.FailureReport());
        met.Should().BeGreaterThan(50);
        passed.Should().BeGreaterThan(50);
    }

    [Theory]
    [InlineData(0.3, -0.001, 3.0)]
    [InlineData(0.3, -0.001, 0.5)]
    [InlineData(0.3, -0.0001, 3.0)]
    [InlineData(0.1, -0.001, 3.0)]
    [InlineData(0.3, -0.01, 3.0)]
    public void A_sphere_falling_past_a_cylinders_rim_within_its_radius_touches_the_rim(double radius, double by, double above)
    {
        // Straight down at radius + by from the side of the tree's trunk (axis (96.25, 95.5), radius 0.4, top 55 m): the
        // sphere comes within radius + by of the rim circle, so it touches it when its centre is sqrt(r² − (r + by)²)
        // above the top.
        foreach (string frame in new[] { "centred", "global" })
        {
            (CastScene scene, V3 axis, double trunk, double height, SurfaceKind kind, uint id) = Cylinder("tree", frame);
            var worst = new Deviations(frame);
            V3 start = axis + new V3(trunk + radius + by, 0, height + above), end = axis + new V3(trunk + radius + by, 0, height - 0.5);
            Vector3 from = scene.World(start), to = scene.World(end);
            CastHit hit = scene.Check(from, 0, to, (float)radius, worst, $"r {radius}, {by} m within it, from {above} m above the top");
            double r = (float)radius, d = r + by;
            output.WriteLine($"[{frame}] {hit}; expected the centre at {axis.Z + height + Math.Sqrt((r * r) - (d * d)):F6} m");
            (hit.Kind, hit.Id).Should().Be((kind, id));
        }
    }
}
