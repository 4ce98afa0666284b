using System.Numerics;
using AcDream.Core.Physics;
using FluentAssertions;
using Xunit;

namespace AcDream.Core.Tests.Casting;

/// <summary>
/// What a cast pays for: its radius is bounded (<see cref="PhysicsConstants.MaxCastRadius"/>; beyond, the call is refused
/// naming <c>options</c>), and of the movers it looks only at those filed in the squares near its path, not at every mover
/// of the box its whole path spans. (Its speed is measured by the benchmarks, not here: these count what it looks at.)
/// </summary>
public class CastCostTests
{
    public static TheoryData<string> Frames() => new() { "centred", "global" };

    private static PhysicsEngine Flat(string frame)
    {
        PhysicsEngine engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(TestData.Holtburg);
        engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(50f), []);
        return engine;
    }

    private static uint Outdoor(float x, float y) =>
        (TestData.Holtburg & 0xFFFF0000u) | (uint)(((int)(x / PhysicsConstants.CellSize) * PhysicsConstants.CellsPerSide) + (int)(y / PhysicsConstants.CellSize) + 1);

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_radius_beyond_the_bound_is_refused_naming_the_request(string frame)
    {
        PhysicsEngine engine = Flat(frame);
        Vector3 o = engine.GetLandblockOrigin(TestData.Holtburg);
        Vector3 from = o + new Vector3(180f, 180f, 51f), to = from + new Vector3(1f, 0f, 0f);
        foreach (float radius in new[] { MathF.BitIncrement(PhysicsConstants.MaxCastRadius), 25f, 1e4f, 1e30f, float.MaxValue })
        {
            Action act = () => engine.Cast(from, 0, to, new CastOptions(radius));
            act.Should().Throw<ArgumentOutOfRangeException>($"{frame}: radius {radius}").WithParameterName("request")
                .WithMessage("*Radius*", $"{frame}: radius {radius}: the message names the radius");
        }

        // At the bound it is answered: a sphere of 24 m over flat ground 1 m below its centre, moving along the ground
        // (free of the triangles it reaches at the start, and within the landblock it meets no other), and one clear of
        // the ground across 150 m of the landblock.
        CastHit at = engine.Cast(from, 0, to, new CastOptions(PhysicsConstants.MaxCastRadius));
        at.Hit.Should().BeFalse($"{frame}: {at}");
        at.Position.Should().Be(to, $"{frame}: {at}");
        Vector3 west = o + new Vector3(20f, 100f, 75f), east = west + new Vector3(150f, 0f, 0f);
        CastHit across = engine.Cast(west, 0, east, new CastOptions(PhysicsConstants.MaxCastRadius));
        across.Hit.Should().BeFalse($"{frame}: {across}");

        // And down onto the ground it stops where the sphere touches it.
        CastHit down = engine.Cast(from + new Vector3(0f, 0f, 40f), 0, from - new Vector3(0f, 0f, 10f), new CastOptions(PhysicsConstants.MaxCastRadius));
        down.Hit.Should().BeTrue($"{frame}: {down}");
        down.Kind.Should().Be(SurfaceKind.Terrain, $"{frame}: {down}");
        (down.Position - o).Z.Should().BeApproximately(74f, 1e-4f, $"{frame}: the centre 24 m over the ground at 50 m: {down}");
    }

    /// <summary>
    /// 10,000 creatures (<see cref="MoverShape.Cylinder"/> 0.3 × 1.8 m) over local 0..150 × 0..150 m, none with its origin
    /// in y 69..75 m; a mover filed in a square (2 m) within the cast's radius and the creatures' reach of its path would be
    /// looked at, none is.
    /// </summary>
    private static PhysicsEngine Crowd(string frame, int count, int seed)
    {
        PhysicsEngine engine = Flat(frame);
        Vector3 o = engine.GetLandblockOrigin(TestData.Holtburg);
        var random = new Random(seed);
        MoverShape creature = MoverShape.Cylinder(0.3f, 1.8f);
        for (uint id = 1; id <= count;)
        {
            float x = random.NextSingle() * 150f, y = random.NextSingle() * 150f;
            if (y >= 69f && y <= 75f)
            {
                continue;
            }

            engine.Movers.Add(id++, creature, o + new Vector3(x, y, 50f), Outdoor(x, y), Quaternion.Identity, MoverState.Creature);
        }

        engine.Movers.Commit();
        return engine;
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_clear_cast_past_many_movers_looks_at_none_of_them(string frame)
    {
        PhysicsEngine crowd = Crowd(frame, 10_000, 29), none = Flat(frame);
        Vector3 o = crowd.GetLandblockOrigin(TestData.Holtburg);
        var casts = new (string Name, Vector3 From, Vector3 To, float Radius)[]
        {
            ("a ray 1 m over the ground", new(1f, 72f, 51f), new(151f, 72f, 51f), 0f),
            ("a sphere of 0.3 m", new(1f, 72f, 51f), new(151f, 72f, 51f), 0.3f),
            ("a ray over the creatures' heads", new(1f, 72f, 53f), new(151f, 72f, 53f), 0f),
            ("a ray down the band, diagonally", new(1f, 70.5f, 51f), new(151f, 73.5f, 51f), 0f),
        };
        _ = crowd.Cast(o + casts[0].From, 0, o + casts[0].To, new CastOptions(0f)); // (the thread's first cast with movers near makes its record)
        foreach (var (name, from, to, radius) in casts)
        {
            long before = Neighbourhood.MoverCall.OfThisThread().Examined;
            CastHit hit = crowd.Cast(o + from, 0, o + to, new CastOptions(radius));
            long examined = Neighbourhood.MoverCall.OfThisThread().Examined - before;
            CastHit expected = none.Cast(o + from, 0, o + to, new CastOptions(radius));
            hit.Should().Be(expected, $"{frame}, {name}: the creatures are clear of the path");
            hit.Hit.Should().BeFalse($"{frame}, {name}: {hit}");
            examined.Should().Be(0, $"{frame}, {name}: no creature is filed in a square near the path");
        }
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_cast_past_many_movers_meets_the_one_in_its_path_looking_at_it_alone(string frame)
    {
        PhysicsEngine crowd = Crowd(frame, 10_000, 30);
        Vector3 o = crowd.GetLandblockOrigin(TestData.Holtburg);
        crowd.Movers.Add(20_000, MoverShape.Cylinder(0.3f, 1.8f), o + new Vector3(100f, 72f, 50f), Outdoor(100f, 72f), Quaternion.Identity, MoverState.Creature);
        crowd.Movers.Commit();
        _ = crowd.Cast(o + new Vector3(1f, 72f, 51f), 0, o + new Vector3(151f, 72f, 51f), new CastOptions(0f));
        foreach (float radius in new[] { 0f, 0.3f })
        {
            long before = Neighbourhood.MoverCall.OfThisThread().Examined;
            CastHit hit = crowd.Cast(o + new Vector3(1f, 72f, 51f), 0, o + new Vector3(151f, 72f, 51f), new CastOptions(radius));
            long examined = Neighbourhood.MoverCall.OfThisThread().Examined - before;
            hit.Hit.Should().BeTrue($"{frame}, radius {radius}: {hit}");
            hit.Kind.Should().Be(SurfaceKind.Mover, $"{frame}, radius {radius}: {hit}");
            hit.Id.Should().Be(20_000u, $"{frame}, radius {radius}: {hit}");
            (hit.Position - o).X.Should().BeApproximately(100f - 0.3f - radius, frame == "global" ? 4e-3f : 1e-4f, $"{frame}, radius {radius}: {hit}");
            examined.Should().BeInRange(1, 2, $"{frame}, radius {radius}: the one creature filed near the path, looked at by the stretch it is in (and the one before)");
        }
    }

    [Fact]
    public void The_cells_with_movers_filed_list_every_mover_filed_in_the_squares_of_a_box_once()
    {
        // 3,000 movers over the 3 × 3 landblocks about Holtburg, some wide (a reach of 3 m grows every box); boxes of
        // every size about them, in the frame of each landblock, across seams, out to where they are clamped.
        var engine = new PhysicsEngine(TestData.Holtburg);
        var random = new Random(29);
        const float size = PhysicsConstants.LandblockSize;
        for (uint id = 1; id <= 3000; id++)
        {
            int dx = random.Next(-1, 2), dy = random.Next(-1, 2);
            uint landblock = TestData.Holtburg + (uint)(dx << 24) + (uint)(dy << 16);
            float x = random.NextSingle() * size, y = random.NextSingle() * size;
            Vector3 world = engine.GetLandblockOrigin(landblock) + new Vector3(x, y, 50f);
            uint cell = (landblock & 0xFFFF0000u) | (uint)(((int)(x / PhysicsConstants.CellSize) * PhysicsConstants.CellsPerSide) + (int)(y / PhysicsConstants.CellSize) + 1);
            MoverShape shape = id % 50 == 0 ? MoverShape.Cylinder(3f, 2f) : MoverShape.Cylinder(0.3f, 1.8f);
            engine.Movers.Add(id, shape, world, cell, Quaternion.Identity, MoverState.Creature);
        }

        engine.Movers.Commit();
        MoverFrame frame = engine.Movers.Hold()!;
        try
        {
            frame.Reach.Should().Be(3f);
            var seen = new HashSet<int>();
            int listed = 0;
            for (int n = 0; n < 2000; n++)
            {
                int lx = 0xA9 + random.Next(-1, 2), ly = 0xB4 + random.Next(-1, 2);
                float extent = n % 10 == 0 ? random.NextSingle() * 600f : random.NextSingle() * 30f;
                var lo = new Vector2((random.NextSingle() * 500f) - 150f, (random.NextSingle() * 500f) - 150f);
                Vector2 hi = lo + new Vector2(random.NextSingle() * extent, random.NextSingle() * extent);
                (int sx0, int sx1) = (Square(lx, lo.X - 3f), Square(lx, hi.X + 3f));
                (int sy0, int sy1) = (Square(ly, lo.Y - 3f), Square(ly, hi.Y + 3f));
                var expected = new HashSet<int>();
                for (int i = 0; i < frame.Count; i++)
                {
                    if (frame.SquareX[i] >= sx0 && frame.SquareX[i] <= sx1 && frame.SquareY[i] >= sy0 && frame.SquareY[i] <= sy1)
                    {
                        expected.Add(i);
                    }
                }

                seen.Clear();
                int twice = -1;
                for (MoverFrame.Filed filed = frame.FiledIn(lx, ly, lo, hi); filed.MoveNext();)
                {
                    twice = seen.Add(filed.Current) ? twice : filed.Current;
                }

                twice.Should().Be(-1, $"box {lo}..{hi} of landblock {lx:X2}{ly:X2}: each mover listed once");
                seen.SetEquals(expected).Should().BeTrue(
                    $"box {lo}..{hi} of landblock {lx:X2}{ly:X2}: listed {seen.Count}, filed there {expected.Count}, missing {string.Join(", ", expected.Except(seen).Take(5))}, not filed there {string.Join(", ", seen.Except(expected).Take(5))}");
                listed += seen.Count;
            }

            listed.Should().BeGreaterThan(20_000, "the boxes hold movers");
        }
        finally
        {
            MoverRegistry.Release(frame);
        }

        // The square of a point of landblock l's frame, clamped as the walk clamps a box (to two landblocks about it).
        static int Square(int l, float local) => MoverFrame.Square(l, Math.Clamp(local, -2f * size, 2f * size));
    }
}
