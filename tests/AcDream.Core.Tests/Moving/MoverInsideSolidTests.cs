using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using AcDream.Testing;
using Xunit.Abstractions;

namespace AcDream.Core.Tests.Moving;

/// <summary>
/// A body that starts inside a mover's solid never ends a move deeper in it (a door slab closed on it, a creature's
/// cylinder it was put in): its penetration depth, measured here in double precision independently of the engine (the
/// shortest push that frees the disc), never grows; and a door does not close on a creature wholly inside its slab.
/// </summary>
[Trait("Mutation", "MoverRegistry")]
public class MoverInsideSolidTests(ITestOutputHelper output)
{
    private const uint Landblock = MoverSmokeTests.Landblock;
    private const uint Outdoor = 0x7A3B0025; // the outdoor cell of (100, 100)
    private const float Ground = MoverSmokeTests.Ground;
    private const float Radius = 0.48f;

    private static readonly Vector2 Door = new(100f, 100f);

    /// <summary>Flat ground in <see cref="Landblock"/>: the frame centred on it, the global one, or one centred on the far corner of the world.</summary>
    private static PhysicsEngine Field(string frame)
    {
        PhysicsEngine engine = frame switch
        {
            "global" => new PhysicsEngine(),
            "far" => new PhysicsEngine(0xFEFEFFFFu),
            _ => new PhysicsEngine(Landblock),
        };
        engine.AddLandblock(Landblock, TestData.FlatTerrain(Ground, Landblock), []);
        return engine;
    }

    private static Vector3 At(PhysicsEngine engine, Vector2 local) => engine.ToWorld(Landblock, new Vector3(local, Ground));

    private static Vector2 Local(PhysicsEngine engine, Vector3 world)
    {
        Vector3 origin = engine.GetLandblockOrigin(Landblock);
        return new Vector2((float)((double)world.X - origin.X), (float)((double)world.Y - origin.Y));
    }

    /// <summary>A closed box X ±w/2, Y ±d/2, Z 0..h, each face wound outward (the top a floor).</summary>
    private static GfxObj Box(float width, float depth, float height)
    {
        float x0 = -width / 2f, x1 = width / 2f, y0 = -depth / 2f, y1 = depth / 2f, h = height;
        return DeterminismWalk.AddPhysicsPolygons(
            new GfxObj { Id = 0x01FF0002, Flags = GfxObjFlags.HasPhysics },
            [
                [new(x0, y0, 0), new(x0, y1, 0), new(x1, y1, 0), new(x1, y0, 0)],
                [new(x0, y0, h), new(x1, y0, h), new(x1, y1, h), new(x0, y1, h)],
                [new(x0, y0, 0), new(x1, y0, 0), new(x1, y0, h), new(x0, y0, h)],
                [new(x0, y1, 0), new(x0, y1, h), new(x1, y1, h), new(x1, y1, 0)],
                [new(x0, y0, 0), new(x0, y0, h), new(x0, y1, h), new(x0, y1, 0)],
                [new(x1, y0, 0), new(x1, y1, 0), new(x1, y1, h), new(x1, y0, h)],
            ]);
    }

    /// <summary>
    /// How deep a disc of <paramref name="radius"/> at <paramref name="p"/> is in a box of half-sides
    /// <paramref name="hx"/> × <paramref name="hy"/> at <paramref name="centre"/> turned by <paramref name="yaw"/>: the
    /// shortest push that frees it (the radius plus the centre's distance to the outline when the centre is inside, the
    /// radius less that distance outside), 0 when apart. Double precision, landblock-local metres.
    /// </summary>
    private static double BoxDepth(Vector2 p, Vector2 centre, double yaw, double hx, double hy, double radius)
    {
        double dx = (double)p.X - centre.X, dy = (double)p.Y - centre.Y;
        double c = Math.Cos(yaw), s = Math.Sin(yaw);
        double u = Math.Abs((c * dx) + (s * dy)), v = Math.Abs((-s * dx) + (c * dy));
        if (u <= hx && v <= hy)
        {
            return radius + Math.Min(hx - u, hy - v);
        }

        double ou = Math.Max(u - hx, 0), ov = Math.Max(v - hy, 0);
        return Math.Max(radius - Math.Sqrt((ou * ou) + (ov * ov)), 0);
    }

    /// <summary>How deep a disc of <paramref name="radius"/> at <paramref name="p"/> is in a cylinder of <paramref name="cylinder"/> about <paramref name="axis"/>, 0 when apart.</summary>
    private static double CylinderDepth(Vector2 p, Vector2 axis, double cylinder, double radius)
    {
        double dx = (double)p.X - axis.X, dy = (double)p.Y - axis.Y;
        return Math.Max(radius + cylinder - Math.Sqrt((dx * dx) + (dy * dy)), 0);
    }

    /// <summary>What rounding an answer to the world frame may move it by: 0.71 of the float spacing of its coordinates.</summary>
    private static double Rounding(Vector3 world) =>
        0.71 * Math.Max(MathF.BitIncrement(MathF.Abs(world.X)) - MathF.Abs(world.X), MathF.BitIncrement(MathF.Abs(world.Y)) - MathF.Abs(world.Y));

    /// <summary>Four walls X ±w/2, Y ±w/2, Z 0..h facing in (a pen): no solid, its inside is free.</summary>
    private static GfxObj Pen(float width, float height)
    {
        float a = -width / 2f, b = width / 2f, h = height;
        return DeterminismWalk.AddPhysicsPolygons(
            new GfxObj { Id = 0x01FF0003, Flags = GfxObjFlags.HasPhysics },
            [
                [new(a, a, h), new(b, a, h), new(b, a, 0), new(a, a, 0)],
                [new(b, b, 0), new(b, b, h), new(a, b, h), new(a, b, 0)],
                [new(a, b, 0), new(a, b, h), new(a, a, h), new(a, a, 0)],
                [new(b, a, 0), new(b, a, h), new(b, b, h), new(b, b, 0)],
            ]);
    }

    [Theory]
    [InlineData("centred")]
    [InlineData("global")]
    [InlineData("far")]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void A_body_in_a_pen_of_walls_facing_in_walks_to_its_far_wall_and_no_further(string frame)
    {
        // Walls facing in wind the other way round the body: they close no solid, and the body inside walks freely
        // until it meets the wall ahead, where it stops at its radius.
        PhysicsEngine engine = Field(frame);
        engine.Movers.Add(9, new MoverShape(Pen(4f, 2.2f)), At(engine, Door), Outdoor, Quaternion.Identity, MoverState.Door);
        engine.Movers.Commit();
        Vector3 start = At(engine, Door + new Vector2(0.5f, 0.2f));
        var body = new MovementOptions { Body = MoverBody.Player };
        ResolveResult small = engine.Resolve(start, Outdoor, new Vector3(0.3f, 0f, 0f), 0.6f, in body);
        output.WriteLine($"{frame}: 0.3 m → {small}");
        small.Outcome.Should().Be(ResolveOutcome.Moved, "nothing stands within its radius");
        Local(engine, small.Position).X.Should().BeApproximately(Door.X + 0.8f, 4e-3f, "(the world frame's float spacing)");
        ResolveResult far = engine.Resolve(start, Outdoor, new Vector3(3f, 0f, 0f), 0.6f, in body);
        output.WriteLine($"{frame}: 3 m → {far}");
        far.Outcome.Should().BeOneOf([ResolveOutcome.Slid, ResolveOutcome.Wall], "the pen's east wall is ahead");
        far.SurfaceNormal.X.Should().BeApproximately(-1f, 1e-6f, "it met the east wall, facing in");
        Local(engine, far.Position).X.Should().BeInRange(Door.X + 2f - Radius - 0.01f, Door.X + 2f - Radius + 4e-3f, "it stops at its radius from the wall, inside the pen");
    }

    [Theory]
    [InlineData("centred", -0.2f)]
    [InlineData("centred", -1f)]
    [InlineData("global", -0.2f)]
    [InlineData("global", -1f)]
    [InlineData("far", -0.2f)]
    [InlineData("far", -1f)]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void A_body_inside_a_door_slab_does_not_walk_deeper_into_it(string frame, float dx)
    {
        // The slab 1.2 × 0.26 × 2.2 m at (100, 100), yaw 0; the body's centre 0.1 m inside its +X face: 0.58 m deep.
        PhysicsEngine engine = Field(frame);
        engine.Movers.Add(9, new MoverShape(Box(1.2f, 0.26f, 2.2f)), At(engine, Door), Outdoor, Quaternion.Identity, MoverState.Door);
        engine.Movers.Commit();
        Vector3 start = At(engine, Door + new Vector2(0.5f, 0f));
        double before = BoxDepth(Local(engine, start), Door, 0, 0.6, 0.13, Radius);
        ResolveResult r = engine.Resolve(start, Outdoor, new Vector3(dx, 0f, 0f), 0.6f, new MovementOptions { Body = MoverBody.Player });
        double after = BoxDepth(Local(engine, r.Position), Door, 0, 0.6, 0.13, Radius);
        output.WriteLine($"{frame}, dx {dx}: {r}, depth {before:F5} → {after:F5} m");
        before.Should().BeApproximately(0.58, 1e-5);
        after.Should().BeLessThanOrEqualTo(before + 1e-6, $"the body ends no deeper in the slab: {r}");
        r.Outcome.Should().Be(ResolveOutcome.Slid, "every part of the move takes it deeper: it meets the nearest side at once");
        r.SurfaceNormal.X.Should().BeApproximately(1f, 1e-6f, "the wall is the slab's nearest face, facing out");
        (r.Position.X - start.X).Should().BeInRange(0f, 0.01f, "it stays, but for the lift out of the nearest side (the sink, a float spacing or so)");
        r.Position.Y.Should().Be(start.Y);
        engine.Resolve(r.Position, r.CellId, Vector3.Zero, 0.6f, new MovementOptions { Body = MoverBody.Player }).Should().Be(r with { Outcome = ResolveOutcome.Moved, SurfaceNormal = Vector3.Zero }, "a zero move gives the answer again");

        // Out through the nearest face, and along it, it moves.
        ResolveResult outward = engine.Resolve(start, Outdoor, new Vector3(-dx, 0f, 0f), 0.6f, new MovementOptions { Body = MoverBody.Player });
        Local(engine, outward.Position).X.Should().BeApproximately(Door.X + 0.5f - dx, 1e-2f, $"it leaves through its nearest face: {outward}");
        ResolveResult along = engine.Resolve(start, Outdoor, new Vector3(0f, 0.1f, 0f), 0.6f, new MovementOptions { Body = MoverBody.Player });
        Local(engine, along.Position).Y.Should().BeApproximately(Door.Y + 0.1f, 1e-2f, $"along its nearest face it moves: {along}");
        BoxDepth(Local(engine, along.Position), Door, 0, 0.6, 0.13, Radius).Should().BeLessThanOrEqualTo(before + 1e-6);
    }

    [Theory]
    [InlineData("centred")]
    [InlineData("global")]
    [InlineData("far")]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void A_body_sliding_along_the_inside_of_a_turned_slab_frame_after_frame_does_not_sink_deeper(string frame)
    {
        // The same move every frame along the slab's nearest side and a little into it, from 0.03 m inside it and from
        // 0.1 m outside it (overlapping it by 0.38 m): the rounding of each answer to the world frame does not add up.
        PhysicsEngine engine = Field(frame);
        const double yaw = 0.4, hx = 0.6, hy = 0.13;
        engine.Movers.Add(9, new MoverShape(Box(1.2f, 0.26f, 2.2f)), At(engine, Door), Outdoor, MoverReference.Yaw(yaw), MoverState.Door);
        engine.Movers.Commit();
        var along = new Vector2((float)Math.Cos(yaw), (float)Math.Sin(yaw));
        var across = new Vector2(-along.Y, along.X); // the slab's +Y, out of its nearest side
        foreach ((float sign, float off) in new[] { (1f, 0.1f), (-1f, 0.1f), (1f, 0.23f), (-1f, 0.23f) })
        {
            var at = new ResolveResult(At(engine, Door + (across * off) - (along * sign * 0.5f)), Outdoor, true);
            double start = BoxDepth(Local(engine, at.Position), Door, yaw, hx, hy, Radius), deepest = start;
            Vector2 delta = (along * sign * 0.02f) - (across * 0.0025f);
            for (int i = 0; i < 50; i++)
            {
                at = engine.Resolve(at.Position, at.CellId, new Vector3(delta, 0f), 0.6f, new MovementOptions { Body = MoverBody.Player });
                double now = BoxDepth(Local(engine, at.Position), Door, yaw, hx, hy, Radius);
                deepest = Math.Max(deepest, now);
            }

            output.WriteLine($"{frame}, {sign}, {off}: {start:F5} m deep at the start, {deepest:F5} at the deepest, ends at {Local(engine, at.Position)}");
            deepest.Should().BeLessThanOrEqualTo(start + 1e-6, $"{frame}, {sign}: the body does not sink into the slab frame after frame");
            Vector2.Dot(Local(engine, at.Position) - Door, along * sign).Should().BeGreaterThan(0f, "it slid more than 0.5 m along the side");
        }
    }

    [Fact]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void A_door_does_not_close_on_a_creature_wholly_inside_its_slab()
    {
        PhysicsEngine engine = Field("centred");
        engine.Movers.Add(9, new MoverShape(Box(1.2f, 0.6f, 2.2f)), At(engine, Door), Outdoor, Quaternion.Identity, MoverState.Door);
        engine.Movers.Add(2, MoverShape.Cylinder(0.15f, 0.3f), At(engine, Door), Outdoor, Quaternion.Identity, MoverState.Creature);
        engine.Movers.Commit();
        engine.Movers.Open(9);
        engine.Movers.Commit();
        engine.Movers.Close(9);
        engine.Movers.Commit();
        engine.Movers.Commit();
        engine.Movers.GetPendingDoorState(9).Should().Be(DoorState.Closing, "the creature stands wholly inside the slab: the door holds");

        engine.Movers.Move(2, At(engine, Door + new Vector2(0f, 0.3f + 0.15f + 0.01f)), Outdoor, Quaternion.Identity);
        engine.Movers.Commit();
        engine.Movers.GetPendingDoorState(9).Should().Be(DoorState.Closed, "closed once the creature stands clear of it");
    }

    public static TheoryData<string, int> Walks() => new() { { "centred", 41 }, { "global", 42 }, { "far", 43 } };

    [Theory]
    [MemberData(nameof(Walks))]
    public void A_body_walking_among_creatures_and_a_slab_never_ends_deeper_in_any(string frame, int seed)
    {
        // A slab turned 0.4 rad and three creatures around it; the body is put down at random every ten moves (every other
        // time inside the slab, else often in one of them) and walks from there with random moves up to 1.2 m. No move ends
        // deeper in any of them than it started by more than one rounding of its answer to the world frame (which the
        // slide's lift keeps from adding up: see the test above).
        PhysicsEngine engine = Field(frame);
        const double yaw = 0.4, hx = 0.6, hy = 0.13;
        engine.Movers.Add(9, new MoverShape(Box(1.2f, 0.26f, 2.2f)), At(engine, Door), Outdoor, MoverReference.Yaw(yaw), MoverState.Door);
        Vector2[] creatures = [Door + new Vector2(-1.3f, 0.4f), Door + new Vector2(1.1f, -0.9f), Door + new Vector2(0.2f, 1.4f)];
        for (int i = 0; i < creatures.Length; i++)
        {
            engine.Movers.Add((uint)(20 + i), MoverKit.Human, At(engine, creatures[i]), Outdoor, Quaternion.Identity, MoverState.Creature);
        }

        engine.Movers.Commit();
        double Depth(Vector2 p, int solid) => solid == 0
            ? BoxDepth(p, Door, yaw, hx, hy, Radius)
            : CylinderDepth(p, creatures[solid - 1], MoverKit.HumanRadius, Radius);

        var random = new Random(seed);
        var options = new MovementOptions { Body = MoverBody.Player };
        ResolveResult at = default;
        int overlapping = 0, inSlab = 0, stopped = 0, moved = 0;
        double worst = double.NegativeInfinity;
        string worstAt = "";
        for (int step = 0; step < 3000; step++)
        {
            if (step % 10 == 0)
            {
                // Every other time within the slab's outline (its frame turned by the yaw), else anywhere around.
                double u = (random.NextDouble() * 2 * hx) - hx, v = (random.NextDouble() * 2 * hy) - hy;
                Vector2 put = step % 20 == 0
                    ? Door + new Vector2((float)((Math.Cos(yaw) * u) - (Math.Sin(yaw) * v)), (float)((Math.Sin(yaw) * u) + (Math.Cos(yaw) * v)))
                    : Door + new Vector2((float)((random.NextDouble() * 4) - 2), (float)((random.NextDouble() * 4) - 2));
                at = engine.Resolve(At(engine, put), Outdoor, Vector3.Zero, 0.6f, options);
            }

            double angle = random.NextDouble() * 2 * Math.PI, length = random.NextDouble() * 1.2;
            var delta = new Vector3((float)(Math.Cos(angle) * length), (float)(Math.Sin(angle) * length), 0f);
            Vector2 from = Local(engine, at.Position);
            ResolveResult r = engine.Resolve(at.Position, at.CellId, delta, 0.6f, options);
            Vector2 to = Local(engine, r.Position);
            double tolerance = Rounding(r.Position) + 1e-6; // (one rounding of the answer: it does not add up, see the test above)
            for (int solid = 0; solid <= creatures.Length; solid++)
            {
                double before = Depth(from, solid), after = Depth(to, solid);
                overlapping += before > 0.01 ? 1 : 0;
                inSlab += solid == 0 && before > Radius ? 1 : 0; // its centre inside the slab
                if (after - before > worst)
                {
                    (worst, worstAt) = (after - before, $"step {step}, solid {solid}: {before:F5} → {after:F5} m, by {delta} → {r}");
                }

                after.Should().BeLessThanOrEqualTo(before + tolerance, $"{frame}, step {step}, solid {solid}: from {from} by {delta} → {r} ({before:F5} → {after:F5} m deep)");
            }

            stopped += r.Outcome == ResolveOutcome.Wall ? 1 : 0;
            moved += Vector2.Distance(from, to) > 0.05f ? 1 : 0;
            at = r;
        }

        output.WriteLine($"{frame}: {overlapping} starts in a solid ({inSlab} with the centre in the slab), {stopped} stopped, {moved} moved; worst deepening {worst:E2} m ({worstAt})");
        inSlab.Should().BeGreaterThan(100, "the walk starts inside the slab often");
        overlapping.Should().BeGreaterThan(300, "and in the solids more often");
        moved.Should().BeGreaterThan(1000, "and moves");
    }
}
