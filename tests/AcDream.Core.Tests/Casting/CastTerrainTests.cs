using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Testing;
using Xunit.Abstractions;
using static AcDream.Testing.CastReference;

namespace AcDream.Core.Tests.Casting;

/// <summary>
/// Casts over the game's terrain triangles against <see cref="CastReference"/>, in both world frames: rays and spheres
/// onto random steep hills, casts grazing a triangle at 0.002–0.05 rad, casts aimed at the shared edges, diagonals and
/// vertices of triangles (cells and landblock seams), and 200 m casts over rolling land across seams. Every contact is
/// within 1e-4 m of the reference's (travel to it, centre and point; normal within 1e-3); none passes the ground.
/// </summary>
public class CastTerrainTests(ITestOutputHelper output)
{
    private static readonly float[] Radii = [0f, 0.3f, 0.05f, 1f, 2.5f];

    /// <summary>A unit vector at <paramref name="azimuth"/> about Z and <paramref name="elevation"/> above the horizontal (radians).</summary>
    private static V3 Direction(double azimuth, double elevation) =>
        new(Math.Cos(azimuth) * Math.Cos(elevation), Math.Sin(azimuth) * Math.Cos(elevation), Math.Sin(elevation));

    /// <summary>The longest travel up to <paramref name="length"/> from <paramref name="p"/> along <paramref name="d"/> that keeps x and y within lo..hi.</summary>
    private static double Within(V3 p, V3 d, double length, double lo, double hi)
    {
        foreach ((double at, double along) in new[] { (p.X, d.X), (p.Y, d.Y) })
        {
            if (along > 0)
            {
                length = Math.Min(length, (hi - at) / along);
            }
            else if (along < 0)
            {
                length = Math.Min(length, (lo - at) / along);
            }
        }

        return length;
    }

    [Theory]
    [MemberData(nameof(CastWorlds.Frames), MemberType = typeof(CastWorlds))]
    public void Rays_and_spheres_onto_random_hills_meet_the_terrain_where_the_reference_does(string frame)
    {
        var worst = new Deviations(frame);
        foreach (int seed in new[] { 1, 2, 3 })
        {
            (CastScene scene, _) = CastWorlds.Hills(seed, frame);
            var random = new Random(seed * 11);
            for (int n = 0; n < 300; n++)
            {
                float r = Radii[n % Radii.Length];
                double x = 2 + (random.NextDouble() * 188), y = 2 + (random.NextDouble() * 188);
                double above = 0.5 + (random.NextDouble() * 40);
                var start = new V3(x, y, scene.Ground(x, y) + r + above);
                while (scene.Clearance(start) < r + 0.01)
                {
                    start += new V3(0, 0, 1); // steep hills: clear the slope beside it too
                }

                V3 d = Direction(random.NextDouble() * 2 * Math.PI, (-85 + (random.NextDouble() * 95)) * Math.PI / 180);
                double length = Within(start, d, 5 + (random.NextDouble() * 75), 1, 191);
                Vector3 from = scene.World(start), to = scene.World(start + (d * length));
                scene.Check(from, 0, to, r, worst, $"seed {seed}, cast {n}");
            }
        }

        output.WriteLine(worst.ToString());
        worst.Hits.Should().BeGreaterThan(500, "most casts reach the ground");
        worst.Misses.Should().BeGreaterThan(20, "some rise away from it");
    }

    public static TheoryData<string, string> Grounds() => new()
    {
        { "hills", "centred" }, { "hills", "global" }, { "rolling", "centred" }, { "rolling", "global" },
    };

    private static CastScene Ground(string ground, string frame) => ground == "hills" ? CastWorlds.Hills(4, frame).Scene : CastWorlds.Rolling(1, frame);

    [Theory]
    [MemberData(nameof(Grounds))]
    public void Casts_grazing_a_terrain_triangle_meet_it_where_the_reference_does(string ground, string frame)
    {
        // Each aimed at a triangle's centroid along the triangle, descending towards it at a small angle from a start
        // 4 m back (inside the triangle seen from above: its centroid is at least 5.6 m from its edges).
        CastScene scene = Ground(ground, frame);
        var random = new Random(5);
        Polygon[] triangles = [.. scene.Shapes.OfType<Polygon>().Where(p => p.Id >> 16 == TestData.Holtburg >> 16)];
        var worst = new Deviations(frame);
        int skipped = 0;
        for (int n = 0; n < 60; n++)
        {
            Polygon triangle = triangles[random.Next(triangles.Length)];
            V3 c = (triangle.Vertices[0] + triangle.Vertices[1] + triangle.Vertices[2]) * (1.0 / 3);
            V3 up = triangle.Normal.Z > 0 ? triangle.Normal : -triangle.Normal;
            V3 side = V3.Cross(up, new V3(Math.Cos(n), Math.Sin(n), 0));
            V3 along = side * (1.0 / side.Length); // a direction in the triangle's plane
            foreach (double angle in new[] { 0.05, 0.01, 0.002 })
            {
                foreach (float r in new[] { 0f, 0.3f })
                {
                    V3 w = (along * Math.Cos(angle)) - (up * Math.Sin(angle));
                    V3 start = c + (up * r) - (w * 4);
                    if (scene.Clearance(start) < r + 0.001)
                    {
                        skipped++; // a fold of the ground rises within the radius of the start
                        continue;
                    }

                    Vector3 from = scene.World(start), to = scene.World(start + (w * 8));
                    CastHit hit = scene.Check(from, 0, to, r, worst, $"{ground}: triangle {triangle.Name}, angle {angle}");
                    hit.Hit.Should().BeTrue();
                }
            }
        }

        output.WriteLine($"{ground}: {worst}; {skipped} starts within a radius of a fold skipped");
        worst.Hits.Should().BeGreaterThan(300);
    }

    [Theory]
    [MemberData(nameof(Grounds))]
    public void Casts_at_shared_edges_diagonals_and_vertices_of_the_triangles_never_pass(string ground, string frame)
    {
        // Targets exactly on a cell's edge, its diagonal (the split the game picks) or a vertex, landblock seams among
        // them on the rolling land (x or y = 0 or 192); approached from above at 5–89° below the horizontal.
        CastScene scene = Ground(ground, frame);
        var random = new Random(6);
        var worst = new Deviations(frame);
        for (int n = 0; n < 400; n++)
        {
            int first = ground == "hills" ? 1 : 0; // the hills' west and south edges border land not loaded or a cliff
            int cx = random.Next(first, 8), cy = random.Next(first, 8);
            double s = random.NextDouble() * 24;
            (double x, double y) = (n % 4) switch
            {
                0 => ((cx * 24) + s, cy * 24.0), // a south edge
                1 => (cx * 24.0, (cy * 24) + s), // a west edge
                2 => SplitsSwToNe((0xA9 * 8) + cx, (0xB4 * 8) + cy) ? ((cx * 24) + s, (cy * 24) + s) : ((cx * 24) + s, (cy * 24) + 24 - s),
                _ => (cx * 24.0, cy * 24.0),
            };
            if (ground == "rolling" && n % 10 == 0)
            {
                (x, y) = n % 20 == 0 ? (n % 40 == 0 ? 0.0 : 192.0, (cy * 24) + s) : ((cx * 24) + s, n % 40 == 10 ? 0.0 : 192.0);
            }

            float r = n % 3 == 0 ? 0.3f : 0f;
            var target = new V3(x, y, scene.Ground(x, y));
            V3 start = default, end = default;
            bool found = false;
            for (int tries = 0; tries < 50 && !found; tries++)
            {
                // The end below the ground beyond the target (not above a ridge's far side), the start clear above it.
                V3 d = Direction(random.NextDouble() * 2 * Math.PI, -(5 + (random.NextDouble() * 84)) * Math.PI / 180);
                start = target - (d * (2 + (random.NextDouble() * 20))) + new V3(0, 0, r / -d.Z);
                end = target + (d * 3) + new V3(0, 0, r / -d.Z);
                double lo = ground == "hills" ? 0 : -192, hi = ground == "hills" ? 192 : 384; // on loaded land
                found = end.Z < scene.Ground(end.X, end.Y) - 0.05 && start.Z > scene.Ground(start.X, start.Y) + r + 0.001 && scene.Clearance(start) > r + 0.001
                    && Math.Min(start.X, Math.Min(start.Y, Math.Min(end.X, end.Y))) >= lo && Math.Max(start.X, Math.Max(start.Y, Math.Max(end.X, end.Y))) <= hi;
            }

            found.Should().BeTrue($"case {n}: a start clear of the ground and an end below it, for ({x}, {y})");
            Vector3 from = scene.World(start), to = scene.World(end);
            CastHit hit = scene.Check(from, 0, to, r, worst, $"{ground}: target ({x}, {y}), case {n}");
            hit.Hit.Should().BeTrue($"case {n}: from above the ground to below it, it never passes: {hit}");
        }

        output.WriteLine($"{ground}: {worst}");
        worst.Hits.Should().BeGreaterThan(300);
    }

    [Theory]
    [MemberData(nameof(CastWorlds.Frames), MemberType = typeof(CastWorlds))]
    public void Casts_of_200_m_over_rolling_land_across_seams_meet_it_where_the_reference_does(string frame)
    {
        CastScene scene = CastWorlds.Rolling(2, frame);
        var random = new Random(7);
        var worst = new Deviations(frame);
        int crossed = 0;
        for (int n = 0; n < 160; n++)
        {
            float r = Radii[n % 4];
            double x = 40 + (random.NextDouble() * 112), y = 40 + (random.NextDouble() * 112);
            var start = new V3(x, y, scene.Ground(x, y) + r + 1 + (random.NextDouble() * 20));
            double azimuth = random.NextDouble() * 2 * Math.PI;
            V3 flat = new V3(Math.Cos(azimuth), Math.Sin(azimuth), 0) * 200;
            V3 end = start + flat + new V3(0, 0, -random.NextDouble() * 50);
            crossed += end.X < 0 || end.X > 192 || end.Y < 0 || end.Y > 192 ? 1 : 0;
            CastHit hit = scene.Check(scene.World(start), 0, scene.World(end), r, worst, $"cast {n}");
            if (hit.Hit)
            {
                hit.Kind.Should().Be(SurfaceKind.Terrain);
            }
        }

        output.WriteLine($"{worst}; {crossed} of 160 end in another landblock");
        crossed.Should().BeGreaterThan(100);
        worst.Hits.Should().BeGreaterThan(60);
    }
}
