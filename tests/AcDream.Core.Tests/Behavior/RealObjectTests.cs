using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using AcDream.Core.Tests.Robustness;
using Xunit.Abstractions;

namespace AcDream.Core.Tests.Behavior;

/// <summary>The real objects: the cottage's shell with the Holtburg cells, the outdoor staircase, the small building on its plinth.</summary>
[Trait("Mutation", "ObjectQueries")]
public class RealObjectTests(ITestOutputHelper output)
{
    private const float Step = 0.6f;
    private const uint Outdoor = 0xA9B40000;

    private static readonly MovementOptions Body = new() { Body = MoverBody.Player };

    /// <summary>The cottage shell's footprint (landblock-local): main block, wing, chimney.</summary>
    internal static readonly (float MinX, float MinY, float MaxX, float MaxY)[] Footprint =
        [(136.3f, 3.5f, 142.5f, 19.5f), (124.5f, 6.5f, 136.3f, 17.1f), (122.5f, 9.7f, 124.5f, 13.9f)];

    internal static bool InsideFootprint(Vector2 p, float grow = 0f) =>
        Footprint.Any(r => p.X > r.MinX - grow && p.X < r.MaxX + grow && p.Y > r.MinY - grow && p.Y < r.MaxY + grow);

    private static PhysicsEngine Holtburg(bool global = false)
    {
        var engine = global ? new PhysicsEngine() : new PhysicsEngine(TestData.Holtburg);
        engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(94f), HoltburgCells.Surfaces(), RealObjects.HoltburgBuildings());
        return engine;
    }

    // Points 0.4 m outside a wall, walking straight at it, and the wall's outward normal.
    public static TheoryData<float, float, float, float> Walls() => new()
    {
        { 142.9f, 12f, -1f, 0f },   // main block, east wall x 142.5
        { 142.9f, 18f, -1f, 0f },
        { 139f, 19.9f, 0f, -1f },   // main block, north wall y 19.5 (under the arched opening, which starts at z 94.85)
        { 139f, 3.1f, 0f, 1f },     // main block, south wall y 3.5
        { 130f, 6.1f, 0f, 1f },     // wing, south wall y 6.5
        { 127f, 17.5f, 0f, -1f },   // wing, north wall y 17.1
        { 122.1f, 12f, 1f, 0f },    // chimney, west wall x 122.5
        { 135.9f, 3.8f, 1f, 0f },   // main block, west wall x 136.3 south of its door
    };

    [Theory]
    [MemberData(nameof(Walls))]
    public void A_point_walking_into_the_shell_from_outside_is_stopped_by_an_outer_wall_with_its_normal(float x, float y, float dx, float dy)
    {
        PhysicsEngine engine = Holtburg();
        var start = new Vector3(x, y, 94f);
        ResolveResult r = engine.Resolve(start, Outdoor, new Vector3(dx, dy, 0f), Step);
        r.Outcome.Should().Be(ResolveOutcome.OuterWall, $"result {r}");
        r.Position.Should().Be(start, $"a refused mover keeps its place: {r}");
        CellIds(r).Should().BeLessThan(0x100, $"still outdoors: {r}");
        Vector3 outward = new(-dx, -dy, 0f);
        Vector3.Distance(r.SurfaceNormal, outward).Should().BeLessThan(1e-5f, $"the wall's normal faces the mover: {r.SurfaceNormal} vs {outward}");
    }

    [Theory]
    [MemberData(nameof(Walls))]
    public void A_body_walking_into_the_shell_from_outside_stops_or_slides_and_never_ends_inside(float x, float y, float dx, float dy)
    {
        PhysicsEngine engine = Holtburg();
        foreach (float angle in new[] { 0f, 20f, -35f, 60f, -80f })
        {
            float a = angle * MathF.PI / 180f;
            var dir = new Vector2((dx * MathF.Cos(a)) - (dy * MathF.Sin(a)), (dx * MathF.Sin(a)) + (dy * MathF.Cos(a)));
            // Start a body's radius further out, so the body starts clear of the wall.
            var at = new ResolveResult(new Vector3(x - (dx * 0.3f), y - (dy * 0.3f), 94f), Outdoor, true);
            float closest = float.MaxValue;
            bool door = false;
            for (int i = 0; i < 30; i++)
            {
                ResolveResult r = engine.Resolve(at.Position, at.CellId, new Vector3(dir * 0.15f, 0f), Step, Body);
                var p = new Vector2(r.Position.X, r.Position.Y);
                if (x < 136.3f && y < 4.2f && (r.CellId == 0xA9B40145 || p.Y > 4.2f + 0.47f))
                {
                    door = true;
                    break; // slid north along the main block's west wall into its door: the door is open
                }

                InsideFootprint(p).Should().BeFalse($"angle {angle}, move {i}: {at} → {r} is inside the shell");
                CellIds(r).Should().BeLessThan(0x100, $"angle {angle}, move {i}: {r}");
                closest = MathF.Min(closest, DistanceOutside(p));
                if (r.Outcome != ResolveOutcome.Moved)
                {
                    r.Outcome.Should().BeOneOf([ResolveOutcome.Slid, ResolveOutcome.OuterWall, ResolveOutcome.Wall, ResolveOutcome.UnloadedAhead], $"angle {angle}, move {i}: {r}");
                }

                at = r;
            }

            if (door)
            {
                continue;
            }

            closest.Should().BeGreaterThan(0.48f - 0.001f, $"angle {angle}: the body keeps its radius from the shell's walls");
            if (MathF.Abs(angle) <= 35f)
            {
                closest.Should().BeLessThan(0.49f, $"angle {angle}: the body reached the wall");
            }
        }
    }

    [Theory]
    [InlineData(0f)]
    [InlineData(15f)]
    [InlineData(-15f)]
    [InlineData(30f)]
    [InlineData(-30f)]
    public void The_west_door_still_enters_0145_for_a_point_and_a_body(float angle)
    {
        PhysicsEngine engine = Holtburg();
        float a = angle * MathF.PI / 180f;
        var dir = new Vector2(MathF.Cos(a), MathF.Sin(a));
        var door = new Vector2(136.3f, 5.15f);
        foreach ((string name, MovementOptions options) in new[] { ("point", MovementOptions.Literal), ("Player", MovementOptions.Player), ("body", Body) })
        {
            Vector2 start = door - (dir * 1.2f);
            var at = new ResolveResult(new Vector3(start, 94f), Outdoor, true);
            uint firstIndoor = 0;
            var trace = new List<string>();
            for (int i = 0; i < 30 && firstIndoor == 0; i++)
            {
                at = engine.Resolve(at.Position, at.CellId, new Vector3(dir * 0.1f, 0f), Step, options);
                trace.Add(at.ToString());
                if (CellIds(at) >= 0x100)
                {
                    firstIndoor = at.CellId;
                }
            }

            firstIndoor.Should().Be(0xA9B40145u, $"{name} at {angle}°: {string.Join("\n", trace)}");
            at.Position.Z.Should().Be(94f, $"{name}: on the room's floor");

            // And back out the way it came.
            for (int i = 0; i < 30 && at.Position.X > 135f; i++)
            {
                at = engine.Resolve(at.Position, at.CellId, new Vector3(dir * -0.1f, 0f), Step, options);
            }

            at.Position.X.Should().BeLessThan(135.1f, $"{name} at {angle}°: left by the door: {at}");
            CellIds(at).Should().BeLessThan(0x100, $"{name}: outdoors again: {at}");
        }
    }

    [Theory]
    [InlineData(129.6f, 0f)]
    [InlineData(129.2f, 20f)]
    [InlineData(130.0f, -20f)]
    public void The_window_of_014C_is_not_passable_from_outside_at_ground_level(float x, float angle)
    {
        PhysicsEngine engine = Holtburg();
        float a = angle * MathF.PI / 180f;
        var dir = new Vector2(MathF.Sin(a), -MathF.Cos(a)); // southward into the wing's north wall y 17.1
        foreach ((string name, MovementOptions options) in new[] { ("point", MovementOptions.Literal), ("Player", MovementOptions.Player), ("body", Body) })
        {
            var at = new ResolveResult(new Vector3(x, 17.9f, 94f), Outdoor, true);
            for (int i = 0; i < 20; i++)
            {
                at = engine.Resolve(at.Position, at.CellId, new Vector3(dir * 0.1f, 0f), Step, options);
                at.Position.Y.Should().BeGreaterThan(17.1f, $"{name}, move {i}: {at}");
                CellIds(at).Should().BeLessThan(0x100, $"{name}, move {i}: {at}");
            }
        }
    }

    public static TheoryData<string> Movers() => ["point", "Player", "swept", "body"];

    private static MovementOptions Options(string name) => name switch
    {
        "point" => MovementOptions.Literal,
        "Player" => MovementOptions.Player,
        "swept" => new MovementOptions { SweepStepLength = 0.48f },
        _ => Body,
    };

    [Theory]
    [MemberData(nameof(Movers))]
    public void The_staircase_is_walked_up_to_the_top_and_back_down_on_its_treads(string mover)
    {
        MovementOptions options = Options(mover);
        var engine = new PhysicsEngine(0xF682FFFF);
        engine.AddLandblock(0xF682FFFF, TestData.FlatTerrain(58.815f, 0xF682FFFF), [], RealObjects.Staircase());
        List<RefFloor> treads = ObjectPlacements.StaircaseInfo().Objects
            .SelectMany(s => ObjectKit.Floors(RealObjects.GfxObjs[s.Id], s.Frame)).Where(f => f.Walkable).ToList();
        treads.Should().HaveCount(8);

        float stepLength = mover == "swept" ? 0.5f : 0.1f;
        var at = new ResolveResult(new Vector3(132f, 73.5f, 58.815f), 0xF6820000, true);
        double maxError = 0;
        int onTreads = 0;
        float top = float.MinValue;
        for (int i = 0; i < 200 && at.Position.Y < 78.9f - stepLength; i++)
        {
            ResolveResult r = engine.Resolve(at.Position, at.CellId, new Vector3(0f, stepLength, 0f), Step, options);
            r.IsRefused.Should().BeFalse($"{mover} up, move {i}: {at} → {r}");
            if (TreadError(treads, r, mover) is double error)
            {
                maxError = Math.Max(maxError, error);
                onTreads++;
            }

            top = MathF.Max(top, r.Position.Z);
            at = r;
        }

        at.Position.Y.Should().BeGreaterThan(78.3f, $"{mover} reached the top: {at}");
        top.Should().BeGreaterThan(61.7f, $"{mover} climbed: {at}");
        for (int i = 0; i < 200 && at.Position.Y > 73.5f; i++)
        {
            ResolveResult r = engine.Resolve(at.Position, at.CellId, new Vector3(0f, -stepLength, 0f), Step, options);
            r.IsRefused.Should().BeFalse($"{mover} down, move {i}: {at} → {r}");
            if (TreadError(treads, r, mover) is double error)
            {
                maxError = Math.Max(maxError, error);
                onTreads++;
            }

            at = r;
        }

        at.Position.Z.Should().Be(58.815f, $"{mover}: back on the ground: {at}");
        at.IsOnGround.Should().BeTrue($"{at}");
        maxError.Should().BeLessThan(1e-4, $"{mover}: largest distance of Z from its tread's plane");
        onTreads.Should().BeGreaterThan(mover == "swept" ? 10 : 50, $"{mover}: moves ending on a tread, compared with its plane");
        output.WriteLine($"{mover}: top z {top:R}, largest distance from a tread's plane {maxError:E2} m, {onTreads} moves on the treads");
    }

    /// <summary>Distance of the result's Z from the plane of the tread under it (null off the treads).</summary>
    private static double? TreadError(List<RefFloor> treads, ResolveResult r, string mover)
    {
        foreach (RefFloor t in treads)
        {
            if (t.SignedInside(r.Position.X, r.Position.Y) > 1e-3)
            {
                // The Player's footing: the highest tread whose edge is within half its radius of its centre holds it.
                double want = mover == "Player"
                    ? treads.Where(u => u.SignedInside(r.Position.X, r.Position.Y) >= -(0.48 * PhysicsConstants.SupportReach) + 1e-4).Max(u => Math.Min(u.ZAt(r.Position.X, r.Position.Y), u.V.Max(v => v.Z)))
                    : t.ZAt(r.Position.X, r.Position.Y);
                double error = Math.Abs(r.Position.Z - want);
                error.Should().BeLessThan(1e-4, $"{mover}: {r} on the tread at {want:R}");
                r.IsOnGround.Should().BeTrue($"{mover}: {r}");
                return error;
            }
        }

        return null;
    }

    /// <summary>The small building's object-local point → landblock-local.</summary>
    private static Vector3 Building(float x, float y, float z)
    {
        var p = ObjectKit.Place(ObjectPlacements.SmallBuildingShell().Frame, new Vector3(x, y, z));
        return new Vector3((float)p.X, (float)p.Y, (float)p.Z);
    }

    private static Vector2 BuildingLocal(Vector3 world)
    {
        Frame f = ObjectPlacements.SmallBuildingShell().Frame;
        Vector3 v = Vector3.Transform(world - f.Origin, Quaternion.Conjugate(Quaternion.Normalize(f.Orientation)));
        return new Vector2(v.X, v.Y);
    }

    [Theory]
    [MemberData(nameof(Movers))]
    public void The_small_building_is_climbed_by_its_ramp_and_entered_only_by_its_doorway(string mover)
    {
        // The fixtures lack the small building's inner cell: past its doorway a point or body walks on in the air 2 m
        // over the terrain, where the Player's edge slide (rightly) holds it at the plinth's edge (tested elsewhere).
        MovementOptions options = mover == "Player" ? MovementOptions.Player with { EdgeSlide = false } : Options(mover);
        PhysicsEngine engine = Holtburg();
        Vector3 forward = Building(0f, 1f, 0f) - Building(0f, 0f, 0f);
        float stepLength = mover == "swept" ? 0.5f : 0.1f;

        // Up the ramp (object-local y −7.15 → −4.7, z 0 → 2) onto the plinth top, z 96.
        var at = new ResolveResult(Building(2f, -8.5f, 0f) with { Z = 94f }, Outdoor, true);
        for (int i = 0; i < 100 && BuildingLocal(at.Position).Y < -3f; i++)
        {
            ResolveResult r = engine.Resolve(at.Position, at.CellId, forward * stepLength, Step, options);
            r.IsRefused.Should().BeFalse($"{mover}, move {i}: {at} → {r}");
            at = r;
        }

        at.Position.Z.Should().BeApproximately(96f, 2e-4f, $"{mover} on the plinth: {at}");
        engine.TryGetGround(at.Position, at.CellId, Step, out float ground, out _, out uint objectId).Should().BeTrue();
        objectId.Should().Be(ObjectPlacements.SmallBuilding, $"{at}, ground {ground}");

        // Beside the doorway (object-local x 2, door x −1…1) the enclosure's front wall y −2.0157 stops it.
        for (int i = 0; i < 30; i++)
        {
            at = engine.Resolve(at.Position, at.CellId, forward * stepLength, Step, options);
            BuildingLocal(at.Position).Y.Should().BeLessThan(-2.0157f - (mover == "body" || mover == "Player" ? 0.479f : 0f), $"{mover}, move {i}: {at}");
            at.Position.Z.Should().BeApproximately(96f, 2e-4f, $"{mover}: {at}");
        }

        // Sideways to the doorway's middle, then through it.
        Vector3 side = Building(1f, 0f, 0f) - Building(0f, 0f, 0f);
        for (int i = 0; i < 100 && BuildingLocal(at.Position).X > 0.05f; i++)
        {
            at = engine.Resolve(at.Position, at.CellId, -side * 0.1f, Step, options);
        }

        BuildingLocal(at.Position).X.Should().BeApproximately(0f, 0.1f, $"{mover} in front of the doorway: {at}");
        for (int i = 0; i < 40 && BuildingLocal(at.Position).Y < 0f; i++)
        {
            at = engine.Resolve(at.Position, at.CellId, forward * stepLength, Step, options);
        }

        BuildingLocal(at.Position).Y.Should().BeGreaterThan(0f, $"{mover} went through the doorway: {at}");

        // From the plinth's side ledge (object-local x 3.65, between the enclosure's side wall x 3.3 and the plinth's
        // edge x 4), walking in along −x: the enclosure's side wall stops it.
        Vector3 ledge = Building(3.65f, 2f, 2f);
        if (mover is "point" or "swept")
        {
            var l = new ResolveResult(ledge, Outdoor, true);
            l = engine.Resolve(l.Position, l.CellId, Vector3.Zero, Step, options);
            l.Position.Z.Should().BeApproximately(96f, 2e-4f, $"on the ledge: {l}");
            for (int i = 0; i < 10; i++)
            {
                l = engine.Resolve(l.Position, l.CellId, -side * 0.1f, Step, options);
                BuildingLocal(l.Position).X.Should().BeGreaterThan(3.3f, $"{mover}, move {i}: {l}");
            }
        }
    }

    private static uint CellIds(ResolveResult r) => r.CellId & 0xFFFF;

    private static float DistanceOutside(Vector2 p)
    {
        // Distance from p (outside) to the footprint's union of rectangles.
        float best = float.MaxValue;
        foreach (var r in Footprint)
        {
            float dx = MathF.Max(MathF.Max(r.MinX - p.X, 0f), p.X - r.MaxX);
            float dy = MathF.Max(MathF.Max(r.MinY - p.Y, 0f), p.Y - r.MaxY);
            best = MathF.Min(best, MathF.Sqrt((dx * dx) + (dy * dy)));
        }

        return best;
    }
}
