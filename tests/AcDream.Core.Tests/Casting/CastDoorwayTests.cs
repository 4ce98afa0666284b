using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using AcDream.Testing;
using Xunit.Abstractions;
using static AcDream.Testing.CastReference;

namespace AcDream.Core.Tests.Casting;

/// <summary>
/// Doors and openings, in both world frames (the contacts against <see cref="CastReference"/>; in the global frame
/// positions within their float rounding): the cottage's west door (the slab a host builds in the doorway of 0x0145,
/// as <c>MoverContactTests</c> and the host register it) blocks a cast through the doorway when closed, from either
/// side, and when opened is passed by a cast that passes Ethereal movers, and blocks again when closed; a 0.3 m sphere
/// fits through the doorway and a 1 m one does not; and a 0.5 m gap between two walls (as an object's walls and as a
/// cell's) stops a 0.3 m sphere where it first touches the gap's edges and lets a 0.2 m one through.
/// </summary>
public class CastDoorwayTests(ITestOutputHelper output)
{
    private const uint Door = ObjectPlacements.CottageWestDoor, MainRoom = 0xA9B40143, Yard = 0xA9B40029;

    /// <summary>Holtburg with the cottage's west door registered (closed) and the reference with and without its slab.</summary>
    private static (CastScene Closed, CastScene Open) WithDoor(string frame)
    {
        CastScene open = CastWorlds.Holtburg(frame, terrain: true);
        (GfxObj slab, Vector3 origin, Quaternion orientation) = CastWorlds.WestDoor();
        Vector3 position = open.Engine.ToWorld(TestData.Holtburg, origin); // a world float: in the global frame 0.8 mm from the local origin
        open.Engine.Movers.Add(Door, new MoverShape(slab), position, ObjectPlacements.CottageWestDoorCell, orientation, MoverState.Door);
        open.Engine.Movers.Commit();
        V3 placed = open.Local(position);
        var at = new Vector3((float)placed.X, (float)placed.Y, (float)placed.Z); // exact: a world float less the landblock's origin
        var closed = new CastScene(open.Engine, frame, TestData.Holtburg, open.Shapes.Concat(CastWorlds.MoverWalls(slab, at, orientation, Door)))
        {
            GeometryRounding = CastWorlds.RealGeometry,
        };
        return (closed, open);
    }

    /// <summary>Through the west doorway at the door's middle (y 5.15) and a little off it, level and sloping; from inside out and from outside in.</summary>
    private static IEnumerable<(string What, uint Cell, V3 Start, V3 End, uint EndCell)> Through()
    {
        foreach ((double y, double z0, double z1) in new[] { (5.15, 95.2, 95.4), (4.8, 95.6, 94.9), (5.6, 94.6, 95.9) })
        {
            yield return ($"out at y {y}", MainRoom, new V3(139, y, z0), new V3(131, y + 0.1, z1), Yard);
            yield return ($"in at y {y}", 0, new V3(131, y + 0.1, z1), new V3(139, y, z0), MainRoom);
        }
    }

    [Theory]
    [MemberData(nameof(CastWorlds.Frames), MemberType = typeof(CastWorlds))]
    public void The_west_door_blocks_a_cast_when_closed_lets_it_through_open_and_blocks_again_closed(string frame)
    {
        (CastScene closed, CastScene open) = WithDoor(frame);
        PhysicsEngine engine = closed.Engine;
        var worst = new Deviations(frame);
        var before = new Dictionary<(string, float, CastFilter), CastHit>();
        engine.Movers.GetPendingDoorState(Door).Should().Be(DoorState.Closed);
        foreach ((string what, uint cell, V3 start, V3 end, _) in Through())
        {
            foreach (float r in new[] { 0f, 0.3f })
            {
                foreach (CastFilter filter in new[] { CastFilter.None, CastFilter.SolidOnly, CastFilter.IgnoreCreatures })
                {
                    CastHit hit = closed.Check(closed.World(start), cell, closed.World(end), r, worst, $"closed, {what}, {filter}", filter);
                    (hit.Kind, hit.Id).Should().Be((SurfaceKind.Mover, Door), $"closed, {what}, r {r}, {filter}: {hit}");
                    before[(what, r, filter)] = hit;
                }
            }
        }

        engine.Movers.Open(Door);
        engine.Movers.Commit();
        engine.Movers.GetPendingDoorState(Door).Should().Be(DoorState.Open);
        foreach ((string what, uint cell, V3 start, V3 end, uint endCell) in Through())
        {
            foreach (float r in new[] { 0f, 0.3f })
            {
                // A camera's cast passes the open (Ethereal) door; a pointer's (no filter) still meets it.
                CastHit passes = open.Check(open.World(start), cell, open.World(end), r, worst, $"open, {what}, solid only", CastFilter.SolidOnly);
                passes.Hit.Should().BeFalse($"open, {what}, r {r}: {passes}");
                passes.CellId.Should().Be(endCell, $"open, {what}: {passes}");
                CastHit pointer = closed.Check(closed.World(start), cell, closed.World(end), r, worst, $"open, {what}, no filter");
                (pointer.Kind, pointer.Id).Should().Be((SurfaceKind.Mover, Door), $"a pointer's ray meets the open door too: {pointer}");
            }
        }

        engine.Movers.Close(Door);
        engine.Movers.Commit();
        engine.Movers.GetPendingDoorState(Door).Should().Be(DoorState.Closed);
        foreach ((string what, uint cell, V3 start, V3 end, _) in Through())
        {
            foreach (float r in new[] { 0f, 0.3f })
            {
                foreach (CastFilter filter in new[] { CastFilter.None, CastFilter.SolidOnly, CastFilter.IgnoreCreatures })
                {
                    CastHit again = engine.Cast(closed.World(start), cell, closed.World(end), new CastOptions(r, filter));
                    again.Should().Be(before[(what, r, filter)], $"closed again, {what}, r {r}, {filter}: the same answer as before it opened");
                }
            }
        }

        output.WriteLine(worst.ToString());
    }

    [Theory]
    [MemberData(nameof(CastWorlds.Frames), MemberType = typeof(CastWorlds))]
    public void A_sphere_of_0_3_m_fits_through_the_west_doorway_and_one_of_1_m_does_not(string frame)
    {
        // The doorway of 0x0145 is 1.9 m wide (y 4.2–6.1) and 2.5 m high (z 94–96.5): no door registered.
        CastScene scene = CastWorlds.Holtburg(frame, terrain: true);
        var worst = new Deviations(frame);
        foreach ((string what, uint cell, V3 start, V3 end, uint endCell) in Through())
        {
            CastHit fits = scene.Check(scene.World(start), cell, scene.World(end), 0.3f, worst, $"0.3 m, {what}");
            fits.Hit.Should().BeFalse($"{what}: {fits}");
            fits.CellId.Should().Be(endCell, $"{what}: {fits}");

        }

        // A 1 m sphere along the doorway's middle (its start and end clear of the room and the ground).
        foreach ((string what, uint cell, V3 start, V3 end, _) in Through().Take(2))
        {
            CastHit wide = scene.Check(scene.World(start), cell, scene.World(end), 1f, worst, $"1 m, {what}");
            wide.Hit.Should().BeTrue($"{what}: {wide}");
            V3 at = scene.Local(wide.Position);
            (cell == MainRoom ? at.X > 136.7 : at.X < 136.3).Should().BeTrue($"{what}: stopped on its own side of the doorway, at {at}");
        }

        output.WriteLine(worst.ToString());
    }

    /// <summary>Two walls 3 m high in the plane x = 0 of their frame, y −3…−0.25 and 0.25…3: a 0.5 m gap at y = 0.</summary>
    private static Vector3[][] GapWalls() => [TestData.Wall(0, -3, 0, -0.25f, 0, 3), TestData.Wall(0, 0.25f, 0, 3, 0, 3)];

    /// <summary>The gap as an object's walls outdoors (at (100, 100, 94), turned 30°) or as a cell's walls (a room of its own at (60, 60, 94)).</summary>
    private static (CastScene Scene, uint Cell, V3 Centre, V3 Across, SurfaceKind Kind, uint Id) Gap(string frame, bool cell)
    {
        PhysicsEngine engine = CastWorlds.NewEngine(frame);
        var shapes = new List<Shape>(CastWorlds.Terrain(CastWorlds.Flat(94f), TestData.Holtburg, default));
        if (cell)
        {
            const uint id = 0xA9B40100;
            var b = new CellBuilder(id, new Vector3(60, 60, 94));
            b.Floor(-5, -5, 5, 5, 0);
            b.Physics([.. CellBuilder.Square(-5, -5, 5, 5, 3).Reverse()]);
            b.Physics(TestData.Wall(-5, -5, 5, -5, 0, 3)).Physics(TestData.Wall(5, -5, 5, 5, 0, 3)).Physics(TestData.Wall(5, 5, -5, 5, 0, 3)).Physics(TestData.Wall(-5, 5, -5, -5, 0, 3));
            foreach (Vector3[] wall in GapWalls())
            {
                b.Physics(wall);
            }

            engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(94f), [b.Build()]);
            shapes.AddRange(Cell(id, b.EnvCell, b.CellStruct));
            return (new CastScene(engine, frame, TestData.Holtburg, shapes), id, new V3(60, 60, 95.5), new V3(1, 0, 0), SurfaceKind.CellWall, id);
        }

        var gfx = AcDream.Testing.DeterminismWalk.AddPhysicsPolygons(new GfxObj { Id = 0x01FF0A01, Flags = GfxObjFlags.HasPhysics }, GapWalls());
        var placement = new Frame { Origin = new Vector3(100, 100, 94), Orientation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 6) };
        engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(94f), [], [new ObjectSurface(gfx, placement, 0)]);
        shapes.AddRange(Model(gfx, placement, SurfaceKind.ObjectWall, gfx.Id));
        double yaw = Math.PI / 6;
        return (new CastScene(engine, frame, TestData.Holtburg, shapes) { GeometryRounding = CastWorlds.RealGeometry }, 0, new V3(100, 100, 95.5), new V3(Math.Cos(yaw), Math.Sin(yaw), 0), SurfaceKind.ObjectWall, gfx.Id);
    }

    public static TheoryData<string, bool> Gaps() => new() { { "centred", false }, { "global", false }, { "centred", true }, { "global", true } };

    [Theory]
    [MemberData(nameof(Gaps))]
    public void A_gap_of_half_a_metre_stops_a_sphere_of_0_3_m_where_it_touches_and_passes_one_of_0_2_m(string frame, bool cell)
    {
        (CastScene scene, uint cellId, V3 centre, V3 across, SurfaceKind kind, uint id) = Gap(frame, cell);
        var along = new V3(-across.Y, across.X, 0);
        var random = new Random(51);
        var worst = new Deviations(frame);
        for (int n = 0; n < 40; n++)
        {
            // Through the gap across the walls' plane, up to 4 cm off its middle, tilted up to 0.2 rad sideways and up or down.
            V3 middle = centre + (along * ((random.NextDouble() - 0.5) * 0.08)) + new V3(0, 0, (random.NextDouble() - 0.5) * 1.5);
            V3 dir = across + (along * ((random.NextDouble() - 0.5) * 0.2)) + new V3(0, 0, (random.NextDouble() - 0.5) * 0.2);
            dir *= 1.0 / dir.Length;
            int side = n % 2 == 0 ? 1 : -1;
            Vector3 from = scene.World(middle - (dir * (2.5 * side))), to = scene.World(middle + (dir * (2.5 * side)));

            CastHit stopped = scene.Check(from, cellId, to, 0.3f, worst, $"0.3 m through the gap, case {n}");
            (stopped.Kind, stopped.Id).Should().Be((kind, id), $"case {n}: {stopped}");
            V3 at = scene.Local(stopped.Position) - centre;
            (V3.Dot(at, across) * side).Should().BeLessThan(0, $"case {n}: stopped before the walls' plane: {stopped}");

            CastHit passes = scene.Check(from, cellId, to, 0.2f, worst, $"0.2 m through the gap, case {n}");
            passes.Hit.Should().BeFalse($"case {n}: {passes}");
        }

        output.WriteLine($"{(cell ? "cell" : "object")}: {worst}");
    }

    [Theory]
    [MemberData(nameof(CastWorlds.Frames), MemberType = typeof(CastWorlds))]
    public void Casts_from_the_yard_in_through_the_west_doorway_meet_what_is_inside(string frame)
    {
        // Rays and spheres from the yard through the west doorway (its opening at x 136.3, y 4.2–6.1, z 94–96.5) into the
        // cottage. Outdoors they meet the outdoors (the ground, the shells, the cells' walls); once the centre has passed
        // in, the building (its cells and the cellar stair, not the ground under its floors or its shell's inner faces).
        CastScene outdoors = CastWorlds.HoltburgOutdoors(frame);
        CastScene inside = CastWorlds.Holtburg(frame, terrain: false, shells: false);
        V3[] doorway = CastWorlds.HoltburgPortals().Single(p => p.Cell == ObjectPlacements.CottageWestDoorCell && p.Other == 0xFFFF).Polygon;
        var random = new Random(52);
        var worst = new Deviations(frame);
        var cells = new Dictionary<uint, int>();
        for (int n = 0; n < 300; n++)
        {
            float r = n % 3 == 0 ? 0f : n % 3 == 1 ? 0.1f : 0.3f;
            var opening = new V3(136.3, 4.2 + r + 0.01 + (random.NextDouble() * (1.9 - (2 * r) - 0.02)), 94 + r + 0.01 + (random.NextDouble() * (2.5 - (2 * r) - 0.02)));
            var start = new V3(128 + (random.NextDouble() * 6), opening.Y + ((random.NextDouble() - 0.5) * 6), 94 + r + 0.05 + (random.NextDouble() * 3));
            V3 end = opening + ((opening - start) * (1.5 * random.NextDouble() * 6 / (opening - start).Length));
            Vector3 from = outdoors.World(start), to = outdoors.World(end);
            V3 a = outdoors.Local(from), b = outdoors.Local(to);
            if (outdoors.Clearance(a) < r + 0.01 || CastWorlds.Crossing(doorway, a, b) is not double enter)
            {
                continue;
            }

            // The outdoors up to where the centre passes in, the building after.
            V3 door = a + ((b - a) * enter);
            Hit? expected = outdoors.Reference.Cast(a, door, r) is Hit before
                ? before with { T = before.T * enter }
                : inside.Reference.Cast(door, b, r) is Hit after ? after with { T = enter + (after.T * (1 - enter)) } : null;
            CastHit hit = outdoors.Engine.Cast(from, 0, to, new CastOptions(r));
            outdoors.Tally(hit, expected, from, to, r, worst, $"cast {n} in through the doorway at {opening}");
            cells[hit.CellId] = cells.GetValueOrDefault(hit.CellId) + 1;
        }

        output.WriteLine($"{worst}; ended in: {string.Join(", ", cells.OrderBy(c => c.Key).Select(c => $"0x{c.Key:X8} {c.Value}"))}");
        worst.Failures.Should().BeEmpty(worst.FailureReport());
        cells.GetValueOrDefault(0xA9B40143u).Should().BeGreaterThan(50, "most go on into the main room");
    }

    [Theory]
    [MemberData(nameof(CastWorlds.Frames), MemberType = typeof(CastWorlds))]
    public void A_ray_in_through_the_doorway_meets_the_stairwell_as_the_same_ray_started_inside_does(string frame)
    {
        // One line from the yard in through the west doorway, across the main room and down the stairwell hole
        // (x 140.5–142.1, y 3.9–8.7 at z 94) to 0x0146's east wall. Started in the yard or in the main room, the cast meets
        // what the building has there: the stairwell's wall (the cottage shell's base, at z 94 under the house, is the
        // outdoors' and not met indoors).
        CastScene inside = CastWorlds.Holtburg(frame, terrain: false, shells: false);
        var worst = new Deviations(frame);
        V3 a = new(129.8707581, 3.8117917, 96.3480530), b = new(143.7759552, 7.3302140, 93.5131912);
        Vector3 to = inside.World(b);
        V3 roomStart = a + ((b - a) * 0.6); // x 138.2: in the main room
        CastHit fromRoom = inside.Check(inside.World(roomStart), MainRoom, to, 0f, worst, "started in the main room");
        (fromRoom.Kind, fromRoom.Id).Should().Be((SurfaceKind.CellWall, 0xA9B40146u), $"{fromRoom}");

        CastHit fromYard = inside.Engine.Cast(inside.World(a), 0, to, new CastOptions(0f));
        output.WriteLine($"[{frame}] from the room: {fromRoom}; from the yard: {fromYard}");
        (fromYard.Kind, fromYard.Id, fromYard.CellId).Should().Be((fromRoom.Kind, fromRoom.Id, fromRoom.CellId), $"from the yard: {fromYard}; from the room: {fromRoom}");
        (inside.Local(fromYard.Position) - inside.Local(fromRoom.Position)).Length.Should().BeLessThan(1e-4 + (2 * CastScene.HalfSpacing(fromRoom.Position)), $"from the yard: {fromYard}; from the room: {fromRoom}");
    }
}
