using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using AcDream.Core.Tests.Robustness;
using Xunit.Abstractions;

namespace AcDream.Core.Tests.Regression;

/// <summary>
/// However many walls stand near a move, none is skipped: the body once kept at most 128 cells, objects and
/// seam copies per call, gathered in grid order, and dropped the rest; with 128 thin posts on the side of a
/// landblock, a 52 m move passed through a beam at the other end. Now the beam stops it with any number of posts,
/// and the body never ends more than 1 mm inside a post, a box or a wall among up to 7,000 objects.
/// </summary>
[Trait("Mutation", "ObjectQueries")]
public class CrowdedWallTests(ITestOutputHelper output)
{
    private const uint Landblock = 0x8080FFFFu;
    private const float Ground = 50f;

    private static readonly GfxObj Trunk = new() { Id = 0x01000001 };

    /// <summary>A post: a Setup of one cylinder.</summary>
    private static ObjectSurface Post(Vector3 at, float radius, float height)
    {
        var setup = new Setup { Id = 0x02000001, NumParts = 1, Parts = [Trunk.Id], CylSpheres = [new CylSphere { Origin = Vector3.Zero, Radius = radius, Height = height }] };
        return new ObjectSurface(setup, new Dictionary<uint, GfxObj> { [Trunk.Id] = Trunk }, ObjectKit.At(at, 0f), 0);
    }

    /// <summary>A closed box from <paramref name="min"/> to <paramref name="max"/> (landblock-local): four vertical sides, a top and a bottom.</summary>
    private static ObjectSurface Box(uint id, Vector3 min, Vector3 max)
    {
        (float x0, float y0, float z0, float x1, float y1, float z1) = (min.X, min.Y, min.Z, max.X, max.Y, max.Z);
        GfxObj box = ObjectKit.Gfx(id,
            [new(x0, y0, z0), new(x0, y1, z0), new(x1, y1, z0), new(x1, y0, z0)],
            [new(x0, y0, z1), new(x1, y0, z1), new(x1, y1, z1), new(x0, y1, z1)],
            TestData.Wall(x0, y0, x1, y0, z0, z1), TestData.Wall(x1, y1, x0, y1, z0, z1),
            TestData.Wall(x0, y1, x0, y0, z0, z1), TestData.Wall(x1, y0, x1, y1, z0, z1));
        return new ObjectSurface(box, ObjectKit.At(Vector3.Zero, 0f), 0);
    }

    private static PhysicsEngine Engine(string frame, List<ObjectSurface> objects)
    {
        PhysicsEngine engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(Landblock);
        engine.AddLandblock(Landblock, TestData.FlatTerrain(Ground, Landblock), [], objects);
        return engine;
    }

    public static TheoryData<string, int> Posts() => new() { { "centred", 127 }, { "centred", 128 }, { "centred", 129 }, { "global", 128 }, { "global", 250 }, { "centred", 1000 } };

    [Theory]
    [MemberData(nameof(Posts))]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void A_long_move_stops_at_a_beam_however_many_posts_stand_elsewhere(string frame, int posts)
    {
        // Thin posts (r 0.02 m, 3 m) on a grid over local x 20..40, y 60..130, away from the path; a beam 0.3 m
        // thick and 40 m long along y at x 100, from 1.0 to 1.7 m above the ground (above the step).
        var objects = new List<ObjectSurface>();
        int columns = Math.Max(1, (int)MathF.Sqrt(posts / 3.5f));
        int rows = (posts + columns - 1) / columns;
        for (int i = 0; i < posts; i++)
        {
            objects.Add(Post(new Vector3(20f + (20f * (i % columns) / Math.Max(1, columns - 1)), 60f + (70f * (i / columns) / Math.Max(1, rows - 1)), Ground), 0.02f, 3f));
        }

        objects.Add(Box(0x01000002, new Vector3(99.85f, 76f, Ground + 1f), new Vector3(100.15f, 116f, Ground + 1.7f)));
        PhysicsEngine engine = Engine(frame, objects);
        Vector3 origin = engine.GetLandblockOrigin(Landblock);
        ResolveResult r = engine.Resolve(origin + new Vector3(50f, 96f, Ground), 0x80800000u, new Vector3(52f, 0f, 0f), 0.6f, MovementOptions.Player);
        float x = r.Position.X - origin.X;
        output.WriteLine($"{frame}, {posts} posts: {r} (local x {x:R})");
        x.Should().BeLessThanOrEqualTo(99.85f - 0.48f + 0.001f, $"{frame}, {posts} posts: the beam stops the body: {r}");
        r.Outcome.Should().NotBe(ResolveOutcome.Moved, $"{r}");
    }

    [Theory]
    [InlineData("centred")]
    [InlineData("global")]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void A_full_wall_stops_a_long_move_and_a_fast_frame_with_many_posts_behind(string frame)
    {
        var objects = new List<ObjectSurface>();
        for (int i = 0; i < 250; i++)
        {
            objects.Add(Post(new Vector3(30f + (0.3f * (i % 25)), 90f + (0.5f * (i / 25)), Ground), 0.02f, 3f)); // behind the start
        }

        objects.Add(Box(0x01000003, new Vector3(99.85f, 76f, Ground), new Vector3(100.15f, 116f, Ground + 3f)));
        PhysicsEngine engine = Engine(frame, objects);
        Vector3 origin = engine.GetLandblockOrigin(Landblock);

        // A 49.6 m move into the full wall, and one 50 m/s frame (1.67 m) into it from 1 m before it.
        ResolveResult far = engine.Resolve(origin + new Vector3(50.5f, 96f, Ground), 0x80800000u, new Vector3(49.6f, 0f, 0f), 0.6f, MovementOptions.Player);
        ResolveResult fast = engine.Resolve(origin + new Vector3(98.37f, 96f, Ground), 0x80800000u, new Vector3(50f / 30f, 0f, 0f), 0.6f, MovementOptions.Player);
        foreach (ResolveResult r in new[] { far, fast })
        {
            (r.Position.X - origin.X).Should().BeLessThanOrEqualTo(99.85f - 0.48f + 0.001f, $"{frame}: {r}");
        }
    }

    [Theory]
    [InlineData("centred", 7000, 3)]
    [InlineData("global", 7000, 4)]
    [InlineData("centred", 800, 5)]
    [Trait("Mutation", "WallSet")]
    public void The_body_never_ends_inside_a_post_or_a_box_among_thousands(string frame, int count, int seed)
    {
        // Posts and boxes at random over the east half of the landblock, many of them packed into a 40 m square
        // where the walks go; walks of 5 cm to 5 m per move (up to 150 m/s frames) with the body and Player.
        var random = new Random(seed);
        var objects = new List<ObjectSurface>();
        var posts = new List<(Vector2 At, float Radius)>();
        var boxes = new List<(Vector2 Min, Vector2 Max, float Top)>();
        for (int i = 0; i < count; i++)
        {
            bool dense = i % 3 == 0;
            var at = new Vector2(dense ? 120f + (float)(random.NextDouble() * 40) : 96f + (float)(random.NextDouble() * 92), dense ? 60f + (float)(random.NextDouble() * 40) : 4f + (float)(random.NextDouble() * 184));
            if (i % 5 == 0)
            {
                var half = new Vector2(0.2f + (float)(random.NextDouble() * 1.5), 0.2f + (float)(random.NextDouble() * 1.5));
                float top = Ground + 0.8f + (float)(random.NextDouble() * 2);
                objects.Add(Box(0x01000100u + (uint)(i % 200), new Vector3(at - half, Ground - 0.5f), new Vector3(at + half, top)));
                boxes.Add((at - half, at + half, top));
            }
            else
            {
                float radius = 0.02f + (float)(random.NextDouble() * 0.3);
                objects.Add(Post(new Vector3(at, Ground), radius, 3f));
                posts.Add((at, radius));
            }
        }

        PhysicsEngine engine = Engine(frame, objects);
        Vector3 origin = engine.GetLandblockOrigin(Landblock);
        double worst = double.NegativeInfinity;
        int answers = 0, stopped = 0;
        foreach (MovementOptions options in new[] { new MovementOptions { Body = MoverBody.Player }, MovementOptions.Player })
        {
            for (int walk = 0, tries = 0; walk < 12 && tries < 500; tries++)
            {
                var at = new ResolveResult(origin + new Vector3(115f + (float)(random.NextDouble() * 50), 55f + (float)(random.NextDouble() * 50), Ground), 0x80800000u, true);
                if (Clearance(at.Position - origin, posts, boxes) < 0.5)
                {
                    continue; // a start inside something: not this test's business
                }

                walk++;

                for (int m = 0; m < 60; m++)
                {
                    double angle = random.NextDouble() * 2 * Math.PI, length = 0.05 + (random.NextDouble() * (random.Next(4) == 0 ? 5 : 0.4));
                    var delta = new Vector3((float)(length * Math.Cos(angle)), (float)(length * Math.Sin(angle)), 0f);
                    ResolveResult r = engine.Resolve(at.Position, at.CellId, delta, 0.6f, options);
                    double clearance = Clearance(r.Position - origin, posts, boxes);
                    worst = Math.Max(worst, 0.48 - clearance);
                    clearance.Should().BeGreaterThanOrEqualTo(0.48 - BodyCheck.OverlapLimit, $"{frame}, {count} objects, walk {walk} move {m}: {at.Position - origin} by {delta} → {r.Position - origin} ({r.Outcome})");
                    answers++;
                    stopped += r.Outcome is ResolveOutcome.Slid or ResolveOutcome.Wall ? 1 : 0;
                    at = r.IsOnGround ? r : r with { Position = r.Position with { Z = Ground } };
                }
            }
        }

        output.WriteLine($"{frame}, {count} objects: {answers} answers, {stopped} slid or stopped; deepest overlap {worst:E2} m");
        answers.Should().BeGreaterThan(600);
        stopped.Should().BeGreaterThan(answers / 10, "the walks met the objects");
    }

    /// <summary>The body's centre's distance (double precision, seen from above) to the nearest post surface or box side: all of them reach into its band.</summary>
    private static double Clearance(Vector3 local, List<(Vector2 At, float Radius)> posts, List<(Vector2 Min, Vector2 Max, float Top)> boxes)
    {
        double best = double.PositiveInfinity;
        foreach ((Vector2 c, float r) in posts)
        {
            double dx = (double)local.X - c.X, dy = (double)local.Y - c.Y;
            best = Math.Min(best, Math.Sqrt((dx * dx) + (dy * dy)) - r);
        }

        foreach ((Vector2 min, Vector2 max, float top) in boxes)
        {
            if (top <= local.Z + 0.6)
            {
                continue; // a step the body climbs, not a wall
            }

            double dx = Math.Max(Math.Max((double)min.X - local.X, local.X - (double)max.X), 0), dy = Math.Max(Math.Max((double)min.Y - local.Y, local.Y - (double)max.Y), 0);
            bool inside = local.X > min.X && local.X < max.X && local.Y > min.Y && local.Y < max.Y;
            best = Math.Min(best, inside ? -1 : Math.Sqrt((dx * dx) + (dy * dy)));
        }

        return best;
    }
}
