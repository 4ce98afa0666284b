using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using AcDream.Core.Tests.Robustness;
using AcDream.Testing;
using Xunit.Abstractions;
using static AcDream.Testing.ReferenceBody;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// The body in three dimensions on the real Holtburg data (<see cref="MovementOptions.Vertical"/>, <see cref="MovementOptions.Footing"/>,
/// <see cref="MovementOptions.EdgeSlide"/>, all in <see cref="MovementOptions.Player"/>), in both world frames, against
/// double-precision references: jumps under ceilings, landings, falls, footing at edges and edge slide. Every answer is
/// checked for the two invariants (a zero move gives it again bit for bit; on the ground exactly when it stands on something).
/// </summary>
public class VerticalMotionTests(ITestOutputHelper output)
{
    private const float Frame = 1f / 30f;
    private const float Gravity = 9.8f;
    private const float Step = 0.6f;
    private const uint Outdoor = 0xA9B40000;
    private const uint MainRoom = 0xA9B40143;
    private static readonly MovementOptions Player = MovementOptions.Player;

    public static TheoryData<string> Frames() => new() { "centred", "global" };

    private static PhysicsEngine Holtburg(string frame, out List<ObjectSurface> objects)
    {
        var engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(TestData.Holtburg);
        objects = RealObjects.HoltburgBuildings();
        engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(94f), HoltburgCells.Surfaces(), objects);
        return engine;
    }

    /// <summary>
    /// One frame of a body under gravity at vertical speed <paramref name="vz"/> (m/s, kept as a caller keeps it: zeroed
    /// by a landing or a head hit), moving <paramref name="across"/>: the displacement exact for constant acceleration.
    /// </summary>
    private static ResolveResult Fly(PhysicsEngine e, ResolveResult at, ref float vz, Vector2 across, MovementOptions options, List<ObjectSurface> objects, string what)
    {
        float dz = 0f;
        if (!at.IsOnGround || vz > 0f)
        {
            float before = vz;
            vz = MathF.Max(vz - (Gravity * Frame), -50f);
            dz = 0.5f * (before + vz) * Frame;
        }

        ResolveResult r = e.Resolve(at.Position, at.CellId, new Vector3(across, dz), Step, options);
        Invariants(e, r, options, objects, what);
        if (r.Outcome == ResolveOutcome.Ceiling || (r.IsOnGround && vz <= 0f))
        {
            vz = r.Outcome == ResolveOutcome.Ceiling ? MathF.Min(vz, 0f) : 0f;
        }

        return r;
    }

    /// <summary>The two invariants of every answer: fixed point, and on the ground exactly when it stands on something.</summary>
    internal static void Invariants(PhysicsEngine e, ResolveResult r, MovementOptions options, List<ObjectSurface> objects, string what)
    {
        (float.IsFinite(r.Position.X) && float.IsFinite(r.Position.Y) && float.IsFinite(r.Position.Z)).Should().BeTrue(what);
        ResolveResult again = e.Resolve(r.Position, r.CellId, Vector3.Zero, Step, options);
        (again.Position, again.CellId, again.IsOnGround).Should().Be((r.Position, r.CellId, r.IsOnGround), $"fixed point: {what} → {r}; in place → {again}");
        if (r.Outcome == ResolveOutcome.Held)
        {
            return;
        }

        bool found = e.TryGetGround(r.Position, r.CellId, PhysicsConstants.GroundTolerance, out float ground, out _, out _);
        Vector3 origin = e.GetLandblockOrigin(r.CellId);
        var local = new Vector2(r.Position.X - origin.X, r.Position.Y - origin.Y);
        bool stands = (found && MathF.Abs(r.Position.Z - ground) <= PhysicsConstants.GroundTolerance)
            || FootingReference.HoldsAnswer(options, HoltburgCells.Surfaces(), objects, r, local);
        r.IsOnGround.Should().Be(stands, $"honest ground: {what} → {r}; ground {(found ? ground.ToString("R") : "none")}");
    }

    private static float TakeOff(float height) => MathF.Sqrt(2f * Gravity * height);

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_jump_under_the_main_rooms_ceiling_stops_at_it_and_lands_in_the_room(string frame)
    {
        PhysicsEngine e = Holtburg(frame, out List<ObjectSurface> objects);
        List<Vec3[]> walls = HoltburgCells.Fixtures.Values.SelectMany(c => WallsOf(c.EnvCell, c.CellStruct)).ToList();
        foreach (Vector2 spot in new Vector2[] { new(138.5f, 6f), new(139.2f, 10.5f), new(141.3f, 10.8f) })
        {
            var at = new ResolveResult(e.ToWorld(TestData.Holtburg, new Vector3(spot, 94f)), MainRoom, true);
            at = e.Resolve(at.Position, at.CellId, Vector3.Zero, Step, Player);
            at.IsOnGround.Should().BeTrue($"{frame}: standing at {spot}");
            float vz = TakeOff(1.64f);
            int headHits = 0;
            double highest = 0;
            for (int f = 0; f < 90 && (f == 0 || !at.IsOnGround); f++)
            {
                string what = $"{frame}, jump at {spot}, frame {f}";
                at = Fly(e, at, ref vz, Vector2.Zero, Player, objects, what);
                at.CellId.Should().Be(MainRoom, $"{what}: never leaves the room: {at}");
                Vector3 local = e.ToLandblockLocal(TestData.Holtburg, at.Position);
                double ceiling = CeilingReference.LowestOver(walls, local.X, local.Y, 0.48, local.Z + 1.835 - 0.01);
                double top = local.Z + 1.835;
                (top - ceiling).Should().BeLessThanOrEqualTo(1e-3, $"{what}: the top {top:R} never passes the ceiling {ceiling:R} by more than 1 mm: {at}");
                highest = Math.Max(highest, top);
                if (at.Outcome == ResolveOutcome.Ceiling)
                {
                    headHits++;
                    (ceiling - top).Should().BeLessThan(1e-3, $"{what}: stopped at the ceiling {ceiling:R}: {at}");
                    at.SurfaceNormal.Z.Should().BeLessThan(-0.99f, $"{what}: the ceiling faces down");
                }
            }

            headHits.Should().Be(1, $"{frame}: the jump at {spot} met the ceiling once");
            at.IsOnGround.Should().BeTrue($"{frame}: landed: {at}");
            e.ToLandblockLocal(TestData.Holtburg, at.Position).Z.Should().Be(94f, "on the room's floor");
            output.WriteLine($"{frame}, {spot}: top reached {highest:F5} m (ceiling 96.8)");
        }
    }

    [Theory]
    [MemberData(nameof(Frames))]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void A_jump_onto_the_plinth_from_beside_it_lands_on_it(string frame)
    {
        PhysicsEngine e = Holtburg(frame, out List<ObjectSurface> objects);
        Frame plinth = ObjectPlacements.SmallBuildingShell().Frame;
        Vector3 Building(float x, float y, float z) => e.ToWorld(TestData.Holtburg, Place(plinth, x, y, z));
        Vector3 inward = Building(-1f, 0f, 0f) - Building(0f, 0f, 0f);

        // Beside the plinth's east side (object-local x 4), on the terrain 2 m below its top, facing it: a jump of 2.6 m.
        var at = e.Resolve(Building(4.6f, 1f, -2f), Outdoor, Vector3.Zero, Step, Player);
        at.IsOnGround.Should().BeTrue($"{frame}: on the terrain beside it: {at}");
        float vz = TakeOff(2.6f);
        bool wasOnTop = false;
        for (int f = 0; f < 60 && !(wasOnTop && at.IsOnGround); f++)
        {
            at = Fly(e, at, ref vz, new Vector2(inward.X, inward.Y) * (4f * Frame), Player, objects, $"{frame}, plinth jump, frame {f}");
            wasOnTop = e.ToLandblockLocal(TestData.Holtburg, at.Position).Z > 95.9f;
        }

        at.IsOnGround.Should().BeTrue($"{frame}: landed: {at}");
        e.ToLandblockLocal(TestData.Holtburg, at.Position).Z.Should().BeApproximately(96f, 2e-4f, $"{frame}: on the plinth's top: {at}");
        e.TryGetGround(at.Position, at.CellId, PhysicsConstants.GroundTolerance, out _, out _, out uint id).Should().BeTrue();
        id.Should().Be(ObjectPlacements.SmallBuilding, "it stands on the small building");
    }

    [Theory]
    [MemberData(nameof(Frames))]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void A_fall_through_the_stairwell_opening_lands_on_the_cellar_floor(string frame)
    {
        PhysicsEngine e = Holtburg(frame, out List<ObjectSurface> objects);
        CellSurface cellar = HoltburgCells.Surface(0xA9B40147);
        foreach (Vector2 spot in new Vector2[] { new(141.3f, 6.3f), new(141.05f, 5.0f), new(141.6f, 7.9f) })
        {
            // Over the opening of 0x0146 in the main room's floor, walked off its edge by a body that does not edge slide.
            var at = new ResolveResult(e.ToWorld(TestData.Holtburg, new Vector3(spot, 94f)), MainRoom, false);
            float vz = 0f;
            var cells = new List<uint>();
            for (int f = 0; f < 60 && (f == 0 || !at.IsOnGround); f++)
            {
                at = Fly(e, at, ref vz, Vector2.Zero, Player, objects, $"{frame}, fall at {spot}, frame {f}");
                if (cells.Count == 0 || cells[^1] != at.CellId)
                {
                    cells.Add(at.CellId);
                }
            }

            at.IsOnGround.Should().BeTrue($"{frame}: landed: {at}");
            at.CellId.Should().Be(0xA9B40147u, $"{frame}: in the cellar: {string.Join(" → ", cells.Select(c => $"0x{c:X8}"))}");
            Vector3 local = e.ToLandblockLocal(TestData.Holtburg, at.Position);
            local.Z.Should().Be(cellar.SampleFloorZ(local.X, local.Y, 95f)!.Value, $"{frame}: on the cellar's floor: {at}");
        }
    }

    [Theory]
    [MemberData(nameof(Frames))]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void A_fall_from_50_m_lands_within_one_frame_of_the_analytic_time(string frame)
    {
        PhysicsEngine e = Holtburg(frame, out List<ObjectSurface> objects);
        var at = new ResolveResult(e.ToWorld(TestData.Holtburg, new Vector3(60f, 60f, 144f)), Outdoor, false);
        float vz = 0f;
        int frames = 0;
        while (!at.IsOnGround && frames < 300)
        {
            at = Fly(e, at, ref vz, Vector2.Zero, Player, objects, $"{frame}, 50 m fall, frame {frames}");
            frames++;
        }

        double analytic = Math.Sqrt(2 * 50 / 9.8);
        output.WriteLine($"{frame}: landed after {frames} frames ({frames * Frame:F4} s), analytic {analytic:F4} s");
        at.IsOnGround.Should().BeTrue();
        e.ToLandblockLocal(TestData.Holtburg, at.Position).Z.Should().Be(94f);
        Math.Abs((frames * Frame) - analytic).Should().BeLessThanOrEqualTo(Frame, "within one frame of √(2h/g)");
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void No_body_ends_past_a_floor_or_ceiling_of_zero_thickness_at_any_speed(string frame)
    {
        // A slab of one polygon facing up at 100 m (no thickness, no walls), over terrain at 94 m; and the main room's ceiling.
        var engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(TestData.Holtburg);
        GfxObj slab = ObjectKit.Gfx(0x01000101, new Vector3[] { new(-3, -3, 0), new(3, -3, 0), new(3, 3, 0), new(-3, 3, 0) });
        List<ObjectSurface> objects = [.. RealObjects.HoltburgBuildings(), new ObjectSurface(slab, ObjectKit.At(new Vector3(60f, 60f, 100f), 0.3f), 0)];
        engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(94f), HoltburgCells.Surfaces(), objects);
        var random = new Random(frame.Length);
        int checkedMoves = 0;
        for (double speed = 0.5; speed <= 50; speed += 0.5)
        {
            float dz = (float)(speed * Frame);
            float phase = (float)random.NextDouble() * dz;

            // Down onto the slab from above: it lands on it.
            var at = new ResolveResult(engine.ToWorld(TestData.Holtburg, new Vector3(60.5f, 59.7f, 100.001f + phase + (3 * dz))), Outdoor, false);
            for (int f = 0; f < 8; f++)
            {
                at = engine.Resolve(at.Position, at.CellId, new Vector3(0, 0, -dz), Step, Player);
                Invariants(engine, at, Player, objects, $"{frame}, down at {speed} m/s, frame {f}");
                engine.ToLandblockLocal(TestData.Holtburg, at.Position).Z.Should().BeGreaterThanOrEqualTo(100f, $"{frame}: {speed} m/s down, frame {f}: above the slab: {at}");
                checkedMoves++;
            }

            at.IsOnGround.Should().BeTrue($"{frame}: {speed} m/s down: on the slab: {at}");

            // Up under the slab from the terrain: the top stops under it.
            at = engine.Resolve(engine.ToWorld(TestData.Holtburg, new Vector3(60.5f, 59.7f, 94f)), Outdoor, Vector3.Zero, Step, Player);
            for (int f = 0; f < 8; f++)
            {
                at = engine.Resolve(at.Position, at.CellId, new Vector3(0, 0, dz), Step, Player);
                Invariants(engine, at, Player, objects, $"{frame}, up at {speed} m/s, frame {f}");
                (engine.ToLandblockLocal(TestData.Holtburg, at.Position).Z + 1.835f).Should().BeLessThanOrEqualTo(100.001f, $"{frame}: {speed} m/s up, frame {f}: under the slab: {at}");
                checkedMoves++;
            }

            // Up under the main room's ceiling (96.8 m).
            at = engine.Resolve(engine.ToWorld(TestData.Holtburg, new Vector3(139.2f, 10.5f, 94f)), MainRoom, Vector3.Zero, Step, Player);
            for (int f = 0; f < 4; f++)
            {
                at = engine.Resolve(at.Position, at.CellId, new Vector3(0, 0, dz), Step, Player);
                at.CellId.Should().Be(MainRoom);
                (engine.ToLandblockLocal(TestData.Holtburg, at.Position).Z + 1.835f).Should().BeLessThanOrEqualTo(96.801f, $"{frame}: {speed} m/s up in the room, frame {f}: {at}");
                checkedMoves++;
            }
        }

        checkedMoves.Should().Be(100 * 20);
    }

    [Theory]
    [MemberData(nameof(Frames))]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void A_body_landing_on_a_face_too_steep_to_stand_on_slides_off_it(string frame)
    {
        // A 60° face (normal Z 0.5: above LandingZ, below FloorZ) 4 m wide, rising from 96 m at y 60 to 97.73 m at y 61,
        // over terrain at 94 m. A body dropped over its middle lands on it (in the air: it cannot stand there), never
        // passes it, slides down it and comes down on the terrain below its foot.
        var engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(TestData.Holtburg);
        float rise = MathF.Sqrt(3f);
        GfxObj roof = ObjectKit.Gfx(0x01000104, new Vector3[] { new(-2, 0, 0), new(2, 0, 0), new(2, 1, rise), new(-2, 1, rise) });
        List<ObjectSurface> objects = [new ObjectSurface(roof, ObjectKit.At(new Vector3(60f, 60f, 96f), 0f), 0)];
        engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(94f), [], objects);
        var at = new ResolveResult(engine.ToWorld(TestData.Holtburg, new Vector3(60f, 60.5f, 100f)), Outdoor, false);
        float vz = 0f;
        int onFace = 0;
        for (int f = 0; f < 120 && (f == 0 || !at.IsOnGround); f++)
        {
            at = Fly(engine, at, ref vz, Vector2.Zero, Player, objects, $"{frame}, steep face, frame {f}");
            Vector3 local = engine.ToLandblockLocal(TestData.Holtburg, at.Position);

            // The face's highest point under the body's disc, in double: the feet never below it.
            double top = Math.Min(61.0, local.Y + 0.48);
            if (top >= 60.0 && Math.Abs(local.X - 60f) < 2f + 0.48f)
            {
                double face = 96.0 + (rise * (top - 60.0));
                (local.Z - face).Should().BeGreaterThan(-1e-3, $"{frame}, frame {f}: never through the face ({face:R}): {at}");
            }

            if (at.Outcome == ResolveOutcome.Slid && at.SurfaceNormal.Z > 0.4f)
            {
                onFace++;
                at.IsOnGround.Should().BeFalse($"{frame}, frame {f}: a face too steep is not stood on: {at}");
                at.SurfaceNormal.Z.Should().BeApproximately(0.5f, 1e-3f, "the face's normal");
                vz = MathF.Max(vz, -2f); // resting against the face, the fall it stopped went along it
            }
        }

        onFace.Should().BeGreaterThan(2, $"{frame}: it landed on the face and slid: {at}");
        at.IsOnGround.Should().BeTrue($"{frame}: down on the terrain: {at}");
        Vector3 end = engine.ToLandblockLocal(TestData.Holtburg, at.Position);
        end.Z.Should().Be(94f);
        end.Y.Should().BeLessThan(60f - 0.4f, $"{frame}: off the face's foot: {at}");
    }

    [Theory]
    [InlineData(0.48f, "centred")]
    [InlineData(0.48f, "global")]
    [InlineData(0.3f, "centred")]
    [InlineData(1.0f, "global")]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void A_floor_holds_a_body_whose_centre_is_up_to_half_its_radius_past_its_edge(float radius, string frame)
    {
        // A 1 × 1 slab 4 m over the terrain (more than the step down): centred d past its east edge, the body stands on it
        // while d < r/2, and is in the air beyond (0.239 m held, 0.241 m not for the player's 0.48 m).
        var engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(TestData.Holtburg);
        GfxObj slab = ObjectKit.Gfx(0x01000102, new Vector3[] { new(-0.5f, -0.5f, 0), new(0.5f, -0.5f, 0), new(0.5f, 0.5f, 0), new(-0.5f, 0.5f, 0) });
        List<ObjectSurface> objects = [new ObjectSurface(slab, ObjectKit.At(new Vector3(60f, 60f, 98f), 0f), 0)];
        engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(94f), [], objects);
        MovementOptions options = Player with { Body = new MoverBody(radius, 1.835f) };
        FloorTriangleInfo[] floors = objects[0].GetFloorTriangles();
        double[] pasts = radius == 0.48f ? [0.0, 0.1, 0.2, 0.239, 0.241, 0.3] : [0.0, 0.4 * radius, 0.499 * radius, 0.501 * radius, 0.6 * radius];
        foreach (double past in pasts)
        {
            var local = new Vector2(60.5f + (float)past, 60.2f);
            ResolveResult r = engine.Resolve(engine.ToWorld(TestData.Holtburg, new Vector3(local, 98f)), Outdoor, Vector3.Zero, Step, options);
            bool held = past < radius * PhysicsConstants.SupportReach;
            FootingReference.Holds(floors, local, 98, radius).Should().Be(held, $"the reference at {past} m");
            r.IsOnGround.Should().Be(held, $"{frame}, radius {radius}: centre {past} m past the edge: {r}");
            engine.ToLandblockLocal(TestData.Holtburg, r.Position).Z.Should().Be(98f, $"{frame}: kept its height: {r}");
            Invariants(engine, r, options, objects, $"{frame}, radius {radius}, {past} m past");
        }
    }

    [Theory]
    [MemberData(nameof(Frames))]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void The_plinth_holds_a_player_0_076_m_past_its_edge_and_edge_slide_walks_it_along_the_edge(string frame)
    {
        PhysicsEngine e = Holtburg(frame, out List<ObjectSurface> objects);
        Frame plinth = ObjectPlacements.SmallBuildingShell().Frame;
        Vector3 Building(float x, float y, float z) => e.ToWorld(TestData.Holtburg, Place(plinth, x, y, z));

        // The plinth's east edge is object-local x 4 (its top at 96); the enclosure's wall at x 3.3 keeps the body's centre east of 3.78.
        ResolveResult past = e.Resolve(Building(4.076f, 1f, 2f), Outdoor, Vector3.Zero, Step, Player);
        past.IsOnGround.Should().BeTrue($"{frame}: 0.076 m past the edge, still on the plinth: {past}");
        e.ToLandblockLocal(TestData.Holtburg, past.Position).Z.Should().Be(96f);

        // Along the edge, 20° outwards, at 4 m/s for 30 frames: it slides along the edge and never steps off.
        Vector3 along = Building(MathF.Sin(0.35f), MathF.Cos(0.35f), 2f) - Building(0f, 0f, 2f);
        var at = e.Resolve(Building(3.9f, -1f, 2f), Outdoor, Vector3.Zero, Step, Player);
        int edgeSlides = 0;
        for (int f = 0; f < 30; f++)
        {
            ResolveResult r = e.Resolve(at.Position, at.CellId, along * (4f * Frame), Step, Player, out MoveReport report);
            Invariants(e, r, Player, objects, $"{frame}, along the edge, frame {f}");
            r.IsOnGround.Should().BeTrue($"{frame}, frame {f}: still on the plinth: {r}");
            e.ToLandblockLocal(TestData.Holtburg, r.Position).Z.Should().Be(96f, $"{frame}, frame {f}");
            Vector2 local = BuildingLocal(plinth, e.ToLandblockLocal(TestData.Holtburg, r.Position));
            local.X.Should().BeLessThanOrEqualTo(4f + (0.48f * PhysicsConstants.SupportReach), $"{frame}, frame {f}: never further out than the support reaches");
            if (report.Wall.Kind == SurfaceKind.FloorEdge)
            {
                edgeSlides++;
                r.SurfaceNormal.X.Should().BeApproximately(Building(1f, 0f, 0f).X - Building(0f, 0f, 0f).X, 1e-3f, "the edge's outward normal");
            }

            at = r;
        }

        edgeSlides.Should().BeGreaterThan(10, $"{frame}: it slid along the edge");
        float travelled = BuildingLocal(plinth, e.ToLandblockLocal(TestData.Holtburg, at.Position)).Y - -1f;
        travelled.Should().BeGreaterThan(3f, $"{frame}: it went on along the edge: {at}");

        // Head on, it stays on the plinth at its edge.
        ResolveResult headOn = e.Resolve(at.Position, at.CellId, (Building(1f, 0f, 2f) - Building(0f, 0f, 2f)) * 0.5f, Step, Player);
        headOn.IsOnGround.Should().BeTrue($"{frame}: head on: {headOn}");
        headOn.Outcome.Should().BeOneOf(ResolveOutcome.Edge, ResolveOutcome.Slid);

        // Without edge slide the same walk leaves the plinth.
        ResolveResult off = e.Resolve(Building(3.9f, -1f, 2f), Outdoor, along * 2f, Step, Player with { EdgeSlide = false });
        off.IsOnGround.Should().BeFalse($"{frame}: without edge slide it steps off: {off}");
    }

    [Theory]
    [MemberData(nameof(Frames))]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void Edge_slide_glides_along_a_rotated_boxs_edge_and_stops_head_on(string frame)
    {
        // A 4 × 4 box turned 30°, its top 2 m over the terrain (more than the step down).
        var engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(TestData.Holtburg);
        GfxObj box = ObjectKit.Gfx(0x01000103, new Vector3[] { new(-2, -2, 0), new(2, -2, 0), new(2, 2, 0), new(-2, 2, 0) });
        Frame placed = ObjectKit.At(new Vector3(80f, 80f, 96f), MathF.PI / 6f);
        List<ObjectSurface> objects = [new ObjectSurface(box, placed, 0)];
        engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(94f), [], objects);
        Vector3 Box(float x, float y) => engine.ToWorld(TestData.Holtburg, Place(placed, x, y, 0f));
        Vector3 east = Box(1f, 0f) - Box(0f, 0f), north = Box(0f, 1f) - Box(0f, 0f);

        // At 45° to the east edge at 4 m/s: 30 frames glide along it, more than 1 m.
        var at = engine.Resolve(Box(1.8f, -1.2f), Outdoor, Vector3.Zero, Step, Player);
        Vector3 heading = Vector3.Normalize(east + north);
        for (int f = 0; f < 30; f++)
        {
            at = engine.Resolve(at.Position, at.CellId, heading * (4f * Frame * 0.5f), Step, Player);
            Invariants(engine, at, Player, objects, $"{frame}, along the box, frame {f}");
            at.IsOnGround.Should().BeTrue($"{frame}, frame {f}: on the box: {at}");
        }

        Vector3 local = engine.ToLandblockLocal(TestData.Holtburg, at.Position) - engine.ToLandblockLocal(TestData.Holtburg, Box(0f, 0f));
        float alongEdge = Vector3.Dot(local, north) - -1.2f;
        alongEdge.Should().BeGreaterThan(1f, $"{frame}: glided along the edge: {at}");

        // Head on at the east edge it stops there: out to where the box still holds it, then no further.
        ResolveResult headOn = engine.Resolve(Box(1.5f, 0f), Outdoor, Vector3.Zero, Step, Player);
        var outcomes = new List<ResolveOutcome>();
        for (int f = 0; f < 10; f++)
        {
            headOn = engine.Resolve(headOn.Position, headOn.CellId, east * (4f * Frame), Step, Player);
            Invariants(engine, headOn, Player, objects, $"{frame}, head on, frame {f}");
            headOn.IsOnGround.Should().BeTrue($"{frame}, frame {f}: head on: {headOn}");
            outcomes.Add(headOn.Outcome);
        }

        // (In the global frame the rounding of positions, 4 mm there, leaves a sliver of the move along the edge: a slide, not a stop.)
        outcomes[^1].Should().BeOneOf([ResolveOutcome.Edge, ResolveOutcome.Slid], $"{frame}: stopped at the edge: {string.Join(", ", outcomes)}");
        ResolveResult again = engine.Resolve(headOn.Position, headOn.CellId, east * (4f * Frame), Step, Player);
        Vector3.Distance(again.Position, headOn.Position).Should().BeLessThan(0.01f, $"{frame}: head on it goes no further: {headOn} → {again}");
        float out_ = Vector3.Dot(engine.ToLandblockLocal(TestData.Holtburg, headOn.Position) - engine.ToLandblockLocal(TestData.Holtburg, Box(0f, 0f)), east);
        out_.Should().BeInRange(2f + 0.2f, 2f + 0.24f, $"{frame}: at the edge, no further out than the support reaches");
    }

    [Theory]
    [MemberData(nameof(Frames))]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void A_wall_is_glided_along_at_45_degrees_and_stops_a_body_head_on(string frame)
    {
        // The cottage's main block, east wall x 142.5, from outside: at 4 m/s, 30 frames.
        PhysicsEngine e = Holtburg(frame, out List<ObjectSurface> objects);
        var at = e.Resolve(e.ToWorld(TestData.Holtburg, new Vector3(143.2f, 8f, 94f)), Outdoor, Vector3.Zero, Step, Player);
        Vector3 start = at.Position;
        var heading = Vector3.Normalize(new Vector3(-1f, 1f, 0f));
        for (int f = 0; f < 30; f++)
        {
            at = e.Resolve(at.Position, at.CellId, heading * (4f * Frame), Step, Player);
            Invariants(e, at, Player, objects, $"{frame}, along the wall, frame {f}");
        }

        (at.Position.Y - start.Y).Should().BeGreaterThan(1f, $"{frame}: glided along the wall: {at}");
        ResolveResult headOn = e.Resolve(at.Position, at.CellId, new Vector3(-4f * Frame, 0f, 0f), Step, Player);
        headOn.Position.X.Should().BeApproximately(at.Position.X, 1e-3f, $"{frame}: head on it stops: {headOn}");
    }

    [Theory]
    [MemberData(nameof(Frames))]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void The_outdoor_staircase_is_climbed_by_a_body_beside_its_treads(string frame)
    {
        // Centre 0.2 m east of the treads' side edge (x 132.75): the treads under the body's edge hold it and it climbs.
        var engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(0xF682FFFF);
        List<ObjectSurface> stairs = RealObjects.Staircase();
        engine.AddLandblock(0xF682FFFF, TestData.FlatTerrain(58.815f, 0xF682FFFF), [], stairs);
        var at = new ResolveResult(engine.ToWorld(0xF682FFFF, new Vector3(132.95f, 73.5f, 58.815f)), 0xF6820000, true);
        float top = float.MinValue;
        for (int i = 0; i < 60 && engine.ToLandblockLocal(0xF682FFFF, at.Position).Y < 78.4f; i++)
        {
            at = engine.Resolve(at.Position, at.CellId, new Vector3(0f, 0.1f, 0f), Step, Player);
            at.IsRefused.Should().BeFalse($"{frame}, move {i}: {at}");
            at.IsOnGround.Should().BeTrue($"{frame}, move {i}: {at}");
            top = MathF.Max(top, engine.ToLandblockLocal(0xF682FFFF, at.Position).Z);
        }

        top.Should().BeGreaterThan(61.7f, $"{frame}: climbed beside the treads: {at}");
        ResolveResult point = engine.Resolve(engine.ToWorld(0xF682FFFF, new Vector3(132.95f, 76f, 58.815f)), 0xF6820000, Vector3.Zero, Step, Player with { Footing = false });
        engine.ToLandblockLocal(0xF682FFFF, point.Position).Z.Should().Be(58.815f, "without footing its centre is over the ground beside them");
    }

    private static Vector3 Place(Frame frame, float x, float y, float z)
    {
        (double px, double py, double pz) = ObjectKit.Place(frame, new Vector3(x, y, z));
        return new Vector3((float)px, (float)py, (float)pz);
    }

    private static Vector2 BuildingLocal(Frame frame, Vector3 local)
    {
        Vector3 v = Vector3.Transform(local - frame.Origin, Quaternion.Conjugate(Quaternion.Normalize(frame.Orientation)));
        return new Vector2(v.X, v.Y);
    }
}
