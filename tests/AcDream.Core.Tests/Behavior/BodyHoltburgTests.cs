using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Testing;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// The body on the real Holtburg cells (flat terrain at the cottages' floor height, 94 m): every doorway
/// wider than the body is passed at angles up to 60° from its normal, both ways; nothing narrower is; and
/// from outside, a building's cell walls stop the body (doors only is geometry) while its doorway lets it in.
/// </summary>
[Trait("Mutation", "WallSet")]
[Trait("Mutation", "BodySweep")]
public class BodyHoltburgTests
{
    private const float GroundZ = 94f;
    private const float Step = BodyDoorways.Step;

    public static TheoryData<string> AllDoorways() => [.. BodyDoorways.Real.Select(d => d.Name)];

    private static Doorway Named(string name) => BodyDoorways.Real.Concat(BodyDoorways.Low).Single(d => d.Name == name);

    private static readonly Lazy<ReferenceBody> Walls = new(() => ReferenceBody.FromCells(HoltburgCells.Fixtures.Values.Select(c => (c.EnvCell, c.CellStruct))));

    internal static PhysicsEngine Engine(string frame = "centred")
    {
        PhysicsEngine engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, FlatTerrain(GroundZ), HoltburgCells.Surfaces());
        engine.AddLandblock(0xA9B3FFFFu, FlatTerrain(GroundZ, 0xA9B3FFFFu), []);
        return engine;
    }

    [Theory]
    [MemberData(nameof(AllDoorways))]
    public void Resolve_DoorwayWiderThanThePlayer_PassedAtAnglesUpTo60Degrees(string doorway)
    {
        Doorway door = Named(doorway);
        PhysicsEngine engine = Engine();
        var passed = new List<float>();
        foreach (float degrees in new[] { 0f, 15f, -15f, 30f, -30f, 45f, -45f, 60f, -60f })
        {
            if (BodyDoorways.Walk(engine, Walls.Value, door, degrees, MovementOptions.Player) is not (List<uint> cells, ResolveResult last))
            {
                continue; // the walls beside the doorway leave no room to come at it from that side at that angle
            }

            string path = string.Join(" → ", cells.Select(c => $"0x{c:X8}"));
            BodyDoorways.IsSide(last.CellId, door.To).Should().BeTrue($"{door} at {degrees}°: through to the other side ({path}; last {last})");
            cells.Should().OnlyContain(c => BodyDoorways.IsSide(c, door.From) || BodyDoorways.IsSide(c, door.To) || c == 0xA9B40145u || c == 0xA9B40170u || c == 0xA9B40173u, $"{door} at {degrees}°: only the cells of the doorway ({path})");
            passed.Add(degrees);
        }

        passed.Should().Contain([0f, 15f, 30f, 45f], $"{door}: passed at {string.Join(", ", passed)}°");
        passed.Should().Contain(d => MathF.Abs(d) == 60f, $"{door}: passed at 60° from one side at least ({string.Join(", ", passed)}°)");
        passed.Count.Should().BeGreaterThanOrEqualTo(7, $"{door}: passed at {string.Join(", ", passed)}°");
    }

    public static TheoryData<string> Doors() => [.. BodyDoorways.Real.Where(d => d.Width < 2f).Select(d => d.Name)];

    [Theory]
    [MemberData(nameof(Doors))]
    public void Resolve_BodyWiderThanTheDoor_NeverPassesIt(string doorway)
    {
        Doorway door = Named(doorway);
        // The real doors (1.9 m) with a body 4 cm wider than the door (the wide openings into the door
        // cell 0x0144 and the cellar's alcove have no room on their far side for a body that wide).
        PhysicsEngine engine = Engine();
        var fat = new MovementOptions { Body = new MoverBody((door.Width / 2) + 0.02f, 1.835f), DoorsOnly = true };
        int tried = 0;
        foreach (float degrees in new[] { 0f, 20f, -20f, 45f, -45f })
        {
            if (BodyDoorways.Walk(engine, Walls.Value, door with { Depth = MathF.Max(door.Depth, fat.Body!.Value.Radius + 0.05f) }, degrees, fat) is not (List<uint> cells, ResolveResult last))
            {
                continue;
            }

            string path = string.Join(" → ", cells.Select(c => $"0x{c:X8}"));
            cells.Should().NotContain(c => BodyDoorways.IsSide(c, door.To) && !BodyDoorways.IsSide(c, door.From), $"{door} at {degrees}° with a body {2 * fat.Body!.Value.Radius} m wide ({path}; last {last})");
            tried++;
        }

        tried.Should().BeGreaterThanOrEqualTo(1, $"{door}: a start with room for the fat body");
    }

    [Theory]
    [InlineData(0.90f, false, false)]
    [InlineData(0.95f, false, false)]
    [InlineData(0.97f, true, null)]
    [InlineData(1.00f, true, true)]
    public void Resolve_PlayerAtADoorNarrowerOrWiderThanItself_PassesOnlyTheWiderOne(float width, bool passesCentred, bool? passesGlobal)
    {
        // Two rooms joined through a 0.4 m door cell of the width given; the player's body is 0.96 m wide.
        // In the global frame at Holtburg (world Y ≈ 34,660 m, float spacing 3.9 mm) the body keeps a skin
        // of twice that from walls, so its world answers never round into one: a door less than 0.976 m
        // wide there is passed or not depending on the angle (not asserted).
        foreach (bool global in new[] { false, true })
        {
            if ((global ? passesGlobal : passesCentred) is not bool passes)
            {
                continue;
            }

            uint prefix = 0xA9B40000u;
            var origin = new Vector3(100, 100, GroundZ);
            var roomA = new CellBuilder(prefix | 0x0100u, origin);
            var roomB = new CellBuilder(prefix | 0x0101u, origin);
            var door = new CellBuilder(prefix | 0x0102u, origin);
            float y0 = 2.5f - (width / 2), y1 = 2.5f + (width / 2);
            BodyCourses.Box(roomA, 0, 0, 4, 5, east: (y0, y1, 2.3f, 0x0102));
            BodyCourses.Box(roomB, 4.4f, 0, 8, 5, west: (y0, y1, 2.3f, 0x0102));
            door.Floor(4, y0, 4.4f, y1, 0);
            door.Physics(BodyCourses.Wall(4, y0, 4.4f, y0, 0, 2.3f)).Physics(BodyCourses.Wall(4.4f, y1, 4, y1, 0, 2.3f));
            door.Portal(0x0100, new Vector3(4.2f, 2.5f, 1), BodyCourses.Opening(4, y0, y1, 2.3f));
            door.Portal(0x0101, new Vector3(4.2f, 2.5f, 1), BodyCourses.Opening(4.4f, y0, y1, 2.3f));
            BodyCourse course = BodyCourses.Create($"{width} m door", 0xA9, 0xB4, global, GroundZ, [roomA, roomB, door], []);
            foreach (float degrees in new[] { 0f, 10f, -25f })
            {
                float a = degrees * MathF.PI / 180;
                Vector3 pos = course.Origin + origin + new Vector3(4.2f - (1.5f * MathF.Cos(a)), 2.5f - (1.5f * MathF.Sin(a)), 0);
                uint cell = roomA.CellId;
                var delta = new Vector3(MathF.Cos(a), MathF.Sin(a), 0) * 0.1f;
                var visited = new HashSet<uint>();
                for (int f = 0; f < 60; f++)
                {
                    ResolveResult r = course.Engine.Resolve(pos, cell, delta, Step, MovementOptions.Player);
                    (pos, cell) = (r.Position, r.CellId);
                    visited.Add(cell);
                }

                visited.Contains(roomB.CellId).Should().Be(passes, $"{course.Name} at {degrees}°: the 0.96 m body {(passes ? "passes" : "does not pass")} (ended at {pos} in 0x{cell:X8}; visited {string.Join(", ", visited.Select(c => $"0x{c:X8}"))})");
            }
        }
    }

    public static TheoryData<string> LowDoorways() => [.. BodyDoorways.Low.Select(d => d.Name)];

    [Theory]
    [MemberData(nameof(LowDoorways))]
    public void Resolve_DoorwayLowerThanTheBody_StopsItBeforeTheStepAndLetsAShorterOneThrough(string doorway)
    {
        Doorway door = Named(doorway);
        // A ceiling lower than the body's height above the floor it would stand on stops it: the player
        // (1.835 m) stays on its side, never in the door cell; a body 1.2 m tall goes through.
        PhysicsEngine engine = Engine();
        foreach (float degrees in new[] { 0f, 30f, -30f })
        {
            (List<uint> tall, ResolveResult stopped) = BodyDoorways.Walk(engine, Walls.Value, door, degrees, MovementOptions.Player, step: 1.1f)!.Value;
            tall.Should().Equal([tall[0]], $"{door} at {degrees}°: the player stays on its side ({string.Join(" → ", tall.Select(c => $"0x{c:X8}"))}; last {stopped})");
            stopped.Outcome.Should().Be(ResolveOutcome.Wall, $"{door} at {degrees}°: {stopped}");
            BodyDoorways.IsSide(stopped.CellId, door.From).Should().BeTrue($"{door} at {degrees}°: {stopped}");

            var shorter = MovementOptions.Player with { Body = new MoverBody(0.48f, 1.2f) };
            (List<uint> cells, ResolveResult last) = BodyDoorways.Walk(engine, Walls.Value, door, degrees, shorter, step: 1.1f)!.Value;
            BodyDoorways.IsSide(last.CellId, door.To).Should().BeTrue($"{door} at {degrees}°: a 1.2 m body passes ({string.Join(" → ", cells.Select(c => $"0x{c:X8}"))}; last {last})");
        }
    }

    [Theory]
    [InlineData("centred")]
    [InlineData("global")]
    public void Resolve_OutdoorsIntoABuildingsWalls_StoppedByThemWithoutDoorsOnly(string frame)
    {
        // Doors only off: the point enters any floor under it, but the body meets the cells' walls from
        // outside, so it stops at them (head on) or slides along them (at an angle), reporting the wall.
        PhysicsEngine engine = Engine(frame);
        Vector3 origin = engine.GetLandblockOrigin(Holtburg);
        var body = new MovementOptions { Body = MoverBody.Player };
        (Vector2 Start, Vector2 Move, Vector2 Normal, float Wall)[] cases =
        [
            (new(138f, 2.5f), new(0, 0.3f), new(0, -1), 3.9f),           // the main room's south wall (y 3.9), head on
            (new(138f, 2.5f), new(0.2f, 0.3f), new(0, -1), 3.9f),        // ... at an angle
            (new(144f, 8f), new(-0.3f, 0.1f), new(1, 0), 142.1f),        // its east wall (x 142.1)
            (new(151f, 13.5f), new(0.3f, -0.2f), new(-1, 0), 152.929f),    // building B's west wall (x 152.929)
        ];
        foreach ((Vector2 start, Vector2 move, Vector2 normal, float wall) in cases)
        {
            var pos = origin + new Vector3(start, GroundZ);
            uint cell = Holtburg & 0xFFFF0000u;
            var delta = new Vector3(move, 0);
            string what = $"{frame}: from {start} by {move}";
            float across = (MathF.Abs(Vector2.Dot(start, normal) - (wall * (normal.X + normal.Y))) + 1f) / MathF.Abs(Vector2.Dot(move, normal));
            ResolveResult point = engine.Resolve(pos, cell, delta * across, Step); // to 1 m inside
            CellIds.IsIndoor(point.CellId).Should().BeTrue($"{what}: without a body the point walks in through the wall ({point})");

            ResolveResult r = default;
            for (int f = 0; f < 12; f++)
            {
                r = engine.Resolve(pos, cell, delta, Step, body);
                (pos, cell) = (r.Position, r.CellId);
                CellIds.IsIndoor(r.CellId).Should().BeFalse($"{what}, frame {f}: the body stays outside ({r})");
            }

            r.Outcome.Should().Be(move.X * normal.Y == move.Y * normal.X ? ResolveOutcome.Wall : ResolveOutcome.Slid, $"{what}: {r}");
            (r.SurfaceNormal.X, r.SurfaceNormal.Y).Should().Be((normal.X, normal.Y), $"{what}: the wall's normal ({r})");
            Vector2 local = new Vector2(r.Position.X, r.Position.Y) - new Vector2(origin.X, origin.Y);
            float gap = MathF.Abs(Vector2.Dot(local, normal) - (wall * (normal.X + normal.Y)));
            gap.Should().BeInRange(0.48f, 0.48f + 0.01f, $"{what}: stopped at the body's radius from the wall ({local})");
        }
    }

    [Theory]
    [InlineData("centred")]
    [InlineData("global")]
    public void Resolve_OutdoorsThroughTheDoorWithoutDoorsOnly_EntersTheBuilding(string frame)
    {
        // Doors only off, body on: the doorway is the way in. The west door into the main room, and building B's north door.
        PhysicsEngine engine = Engine(frame);
        var body = new MovementOptions { Body = MoverBody.Player };
        foreach (Doorway door in BodyDoorways.Real.Where(d => d.From == 0))
        {
            foreach (float degrees in new[] { 0f, 30f, -30f })
            {
                (List<uint> cells, ResolveResult last) = BodyDoorways.Walk(engine, Walls.Value, door, degrees, body)!.Value;
                BodyDoorways.IsSide(last.CellId, door.To).Should().BeTrue($"{frame}: {door} at {degrees}° ({string.Join(" → ", cells.Select(c => $"0x{c:X8}"))}; last {last})");
            }
        }
    }
}
