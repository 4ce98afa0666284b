using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Testing;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// The portal search's limits and edges, each at its boundary: how many doorways one move passes
/// (<see cref="PhysicsConstants.MaxPortalHops"/>), how many cells one call visits
/// (<see cref="PhysicsConstants.MaxCellVisits"/>), which floor openings a walking and a falling mover pass,
/// and a door to the outdoors on a landblock's edge (the next landblock's terrain, unloaded, off the world).
/// Both world frames.
/// </summary>
[Trait("Mutation", "PortalTraversal")]
public class PortalSearchTests
{
    private const float Step = 0.6f;
    private const float GroundZ = 94f;

    public static TheoryData<string> Frames => new() { "global", "centred" };

    private static PhysicsEngine Engine(string frame) => frame == "global" ? new PhysicsEngine() : new PhysicsEngine(Holtburg);

    /// <summary>
    /// Cells 1 m wide in a row along X (cell i over x = 100 + i .. 101 + i), each joined to the next by a
    /// doorway as wide as the cell: a move from the middle of cell 0 crosses as many doorways as metres.
    /// </summary>
    private static PhysicsEngine Row(string frame, int cells)
    {
        var list = new List<CellSurface>();
        for (int i = 0; i < cells; i++)
        {
            float x0 = 100f + i, x1 = x0 + 1f;
            var inside = new Vector3(x0 + 0.5f, 101f, 1f);
            var b = new CellBuilder(0xA9B40100u + (uint)i).Floor(x0, 100f, x1, 102f, GroundZ);
            if (i > 0)
            {
                b.Portal((ushort)(0x0100 + i - 1), inside, Wall(x0, 102f, x0, 100f, GroundZ, GroundZ + 2.5f));
            }

            if (i < cells - 1)
            {
                b.Portal((ushort)(0x0101 + i), inside, Wall(x1, 100f, x1, 102f, GroundZ, GroundZ + 2.5f));
            }

            list.Add(b.Build());
        }

        PhysicsEngine engine = Engine(frame);
        engine.AddLandblock(Holtburg, FlatTerrain(GroundZ - 20f), list);
        return engine;
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_move_passes_as_many_doorways_as_the_hop_limit_and_a_wall_at_one_more(string frame)
    {
        PhysicsEngine engine = Row(frame, PhysicsConstants.MaxPortalHops + 2);
        Vector3 start = engine.GetLandblockOrigin(Holtburg) + new Vector3(100.5f, 101f, GroundZ);

        ResolveResult through = engine.Resolve(start, 0xA9B40100u, new Vector3(PhysicsConstants.MaxPortalHops, 0f, 0f), Step);
        (through.Outcome, through.CellId).Should().Be((ResolveOutcome.Moved, 0xA9B40100u + PhysicsConstants.MaxPortalHops), $"{frame}: {through}");
        Vector3.Distance(through.Position, start + new Vector3(PhysicsConstants.MaxPortalHops, 0f, 0f)).Should().BeLessThan(0.01f, $"{frame}: {through}");

        ResolveResult beyond = engine.Resolve(start, 0xA9B40100u, new Vector3(PhysicsConstants.MaxPortalHops + 1, 0f, 0f), Step);
        (beyond.Outcome, beyond.Position, beyond.CellId).Should().Be((ResolveOutcome.Wall, start, 0xA9B40100u), $"{frame}: one doorway more than the limit: {beyond}");
    }

    /// <summary>
    /// A room with no floor under the end point, only openings to the cells below (all holding the end point),
    /// each leading to an empty cell but the last, whose floor takes the mover: with as many openings as the visit
    /// limit allows (the room, the empty cells, the last) the mover lands; with one more, the last is never reached.
    /// </summary>
    [Theory]
    [MemberData(nameof(Frames))]
    public void A_move_needing_as_many_cell_visits_as_the_limit_lands_and_one_more_is_refused(string frame)
    {
        foreach ((int empty, bool lands) in new[] { (PhysicsConstants.MaxCellVisits - 2, true), (PhysicsConstants.MaxCellVisits - 1, false) })
        {
            var room = new CellBuilder(0xA9B40100u).Floor(100f, 100f, 102f, 102f, GroundZ);
            var cells = new List<CellSurface>();
            for (int i = 0; i <= empty; i++)
            {
                uint id = 0xA9B40101u + (uint)i;
                room.Portal((ushort)id, new Vector3(103f, 101f, GroundZ + 1f), Square(102f, 100f, 104f, 102f, GroundZ));
                var below = new CellBuilder(id).Portal(0x0100, new Vector3(103f, 101f, GroundZ - 1f), Square(102f, 100f, 104f, 102f, GroundZ));
                cells.Add((i == empty ? below.Floor(102f, 100f, 104f, 102f, GroundZ - 0.3f) : below).Build());
            }

            cells.Add(room.Build());
            PhysicsEngine engine = Engine(frame);
            engine.AddLandblock(Holtburg, FlatTerrain(GroundZ - 20f), cells);
            Vector3 start = engine.GetLandblockOrigin(Holtburg) + new Vector3(101.5f, 101f, GroundZ);

            ResolveResult r = engine.Resolve(start, 0xA9B40100u, new Vector3(1f, 0f, 0f), Step);
            if (lands)
            {
                (r.Outcome, r.CellId, r.Position.Z).Should().Be((ResolveOutcome.Moved, 0xA9B40101u + (uint)empty, GroundZ - 0.3f), $"{frame}, {empty} empty cells: {r}");
            }
            else
            {
                (r.IsRefused, r.Position, r.CellId).Should().Be((true, start, 0xA9B40100u), $"{frame}, {empty} empty cells: {r}");
            }
        }
    }

    /// <summary>
    /// A shaft: a room whose floor has a hole over a side cell with no floor there, whose floor opening 10 m
    /// below leads into a shaft cell with no floor, and on through its bottom opening to the bottom cell. A mover
    /// that drops in through the hole falls on down the shaft to the bottom; one walking in the side cell over the
    /// same opening (10 m below its feet) does not pass it, and nothing else takes it there: it is refused.
    /// </summary>
    [Theory]
    [MemberData(nameof(Frames))]
    public void A_falling_mover_passes_a_floor_opening_far_below_and_a_walking_one_does_not(string frame)
    {
        const float Bottom = GroundZ - 21f;
        Vector3[] hole = Square(102f, 100f, 104f, 102f, GroundZ), far = Square(102f, 100f, 104f, 102f, GroundZ - 10f), foot = Square(102f, 100f, 104f, 102f, GroundZ - 20f);
        CellSurface room = new CellBuilder(0xA9B40100u).Floor(100f, 100f, 102f, 102f, GroundZ).Portal(0x0101, new Vector3(103f, 101f, GroundZ + 1f), hole).Build();
        CellSurface side = new CellBuilder(0xA9B40101u).Floor(98f, 100f, 102f, 102f, GroundZ)
            .Portal(0x0100, new Vector3(103f, 101f, GroundZ - 1f), hole).Portal(0x0102, new Vector3(103f, 101f, GroundZ - 5f), far).Build();
        CellSurface shaft = new CellBuilder(0xA9B40102u)
            .Portal(0x0101, new Vector3(103f, 101f, GroundZ - 15f), far).Portal(0x0103, new Vector3(103f, 101f, GroundZ - 15f), foot).Build();
        CellSurface bottom = new CellBuilder(0xA9B40103u).Floor(102f, 100f, 104f, 102f, Bottom).Portal(0x0102, new Vector3(103f, 101f, Bottom + 0.5f), foot).Build();
        PhysicsEngine engine = Engine(frame);
        engine.AddLandblock(Holtburg, FlatTerrain(GroundZ - 30f), [room, side, shaft, bottom]);
        Vector3 start = engine.GetLandblockOrigin(Holtburg) + new Vector3(101.5f, 101f, GroundZ);

        ResolveResult fell = engine.Resolve(start, 0xA9B40100u, new Vector3(1f, 0f, 0f), Step);
        (fell.Outcome, fell.CellId, fell.Position.Z).Should().Be((ResolveOutcome.Moved, 0xA9B40103u, Bottom), $"{frame}: dropped through the hole and on down the shaft: {fell}");

        ResolveResult walked = engine.Resolve(start, 0xA9B40101u, new Vector3(1f, 0f, 0f), Step);
        (walked.IsRefused, walked.Position, walked.CellId).Should().Be((true, start, 0xA9B40101u), $"{frame}: a walking mover does not pass an opening 10 m below its feet: {walked}");
    }

    /// <summary>
    /// A doorway into a room whose floor has an opening 10 m down just beyond it (into a shaft with a floor at its
    /// foot): a mover walking through the doorway onto the opening walks, it does not fall through; it is refused.
    /// </summary>
    [Theory]
    [MemberData(nameof(Frames))]
    public void A_mover_walking_through_a_doorway_does_not_fall_through_an_opening_far_below(string frame)
    {
        Vector3[] far = Square(102f, 100f, 104f, 102f, GroundZ - 10f), foot = Square(102f, 100f, 104f, 102f, GroundZ - 20f);
        CellSurface hall = new CellBuilder(0xA9B40100u).Floor(98f, 100f, 102f, 102f, GroundZ)
            .Portal(0x0101, new Vector3(101f, 101f, GroundZ + 1f), Wall(102f, 100f, 102f, 102f, GroundZ, GroundZ + 2.5f)).Build();
        CellSurface room = new CellBuilder(0xA9B40101u).Floor(104f, 100f, 106f, 102f, GroundZ)
            .Portal(0x0100, new Vector3(103f, 101f, GroundZ + 1f), Wall(102f, 102f, 102f, 100f, GroundZ, GroundZ + 2.5f))
            .Portal(0x0102, new Vector3(103f, 101f, GroundZ + 1f), far).Build();
        CellSurface shaft = new CellBuilder(0xA9B40102u)
            .Portal(0x0101, new Vector3(103f, 101f, GroundZ - 15f), far).Portal(0x0103, new Vector3(103f, 101f, GroundZ - 15f), foot).Build();
        CellSurface bottom = new CellBuilder(0xA9B40103u).Floor(102f, 100f, 104f, 102f, GroundZ - 21f)
            .Portal(0x0102, new Vector3(103f, 101f, GroundZ - 20.5f), foot).Build();
        PhysicsEngine engine = Engine(frame);
        engine.AddLandblock(Holtburg, FlatTerrain(GroundZ - 30f), [hall, room, shaft, bottom]);
        Vector3 start = engine.GetLandblockOrigin(Holtburg) + new Vector3(101.5f, 101f, GroundZ);

        ResolveResult r = engine.Resolve(start, 0xA9B40100u, new Vector3(1f, 0f, 0f), Step);
        (r.IsRefused, r.Position, r.CellId).Should().Be((true, start, 0xA9B40100u), $"{frame}: walked through the doorway onto an opening 10 m below: {r}");
    }

    /// <summary>
    /// Through a doorway into a room and on into that room's far wall beside its next doorway: refused as a wall,
    /// with that wall's normal, facing the mover (the wall it met, though it met it beyond the doorway).
    /// </summary>
    [Theory]
    [MemberData(nameof(Frames))]
    public void A_move_through_a_doorway_into_the_next_rooms_wall_reports_that_wall(string frame)
    {
        CellSurface a = new CellBuilder(0xA9B40100u).Floor(100f, 100f, 102f, 104f, GroundZ)
            .Portal(0x0101, new Vector3(101f, 102f, GroundZ + 1f), Wall(102f, 100f, 102f, 104f, GroundZ, GroundZ + 2.5f)).Build();
        CellSurface b = new CellBuilder(0xA9B40101u).Floor(102f, 100f, 104f, 104f, GroundZ)
            .Portal(0x0100, new Vector3(103f, 102f, GroundZ + 1f), Wall(102f, 104f, 102f, 100f, GroundZ, GroundZ + 2.5f))
            .Portal(0x0102, new Vector3(103f, 102f, GroundZ + 1f), Wall(104f, 103f, 104f, 104f, GroundZ, GroundZ + 2.5f)).Build();
        CellSurface c = new CellBuilder(0xA9B40102u).Floor(104f, 100f, 106f, 104f, GroundZ)
            .Portal(0x0101, new Vector3(105f, 102f, GroundZ + 1f), Wall(104f, 104f, 104f, 103f, GroundZ, GroundZ + 2.5f)).Build();
        PhysicsEngine engine = Engine(frame);
        engine.AddLandblock(Holtburg, FlatTerrain(GroundZ - 20f), [a, b, c]);
        Vector3 start = engine.GetLandblockOrigin(Holtburg) + new Vector3(101.5f, 101f, GroundZ);

        ResolveResult r = engine.Resolve(start, 0xA9B40100u, new Vector3(3f, 0f, 0f), Step);
        (r.Outcome, r.Position, r.SurfaceNormal).Should().Be((ResolveOutcome.Wall, start, new Vector3(-1f, 0f, 0f)), $"{frame}: {r}");
    }

    /// <summary>
    /// A cellar whose stair (a ramp of its floor) rises to 0.2 m under an opening in its ceiling, the room's floor 3 m
    /// up around it: a mover at the ramp's top stepping on past the opening's edge stands on the room's floor beside
    /// the opening (0.2 m up), not on the cellar's floor under it (2.8 m down).
    /// </summary>
    [Theory]
    [MemberData(nameof(Frames))]
    public void At_the_top_of_a_stair_the_floor_above_beside_the_opening_wins_over_the_cellar_floor_below(string frame)
    {
        Vector3[] opening = Square(100f, 100f, 104f, 102f, GroundZ + 3f);
        CellSurface cellar = new CellBuilder(0xA9B40100u).Floor(94f, 98f, 110f, 104f, GroundZ)
            .Physics(new(100f, 100f, GroundZ + 0.8f), new(103.5f, 100f, GroundZ + 2.8f), new(103.5f, 102f, GroundZ + 2.8f), new(100f, 102f, GroundZ + 0.8f))
            .Portal(0x0101, new Vector3(102f, 101f, GroundZ + 1f), opening).Build();
        CellSurface room = new CellBuilder(0xA9B40101u).Floor(104f, 98f, 110f, 104f, GroundZ + 3f).Floor(94f, 98f, 100f, 104f, GroundZ + 3f)
            .Portal(0x0100, new Vector3(102f, 101f, GroundZ + 4f), opening).Build();
        PhysicsEngine engine = Engine(frame);
        engine.AddLandblock(Holtburg, FlatTerrain(GroundZ - 20f), [cellar, room]);
        Vector3 origin = engine.GetLandblockOrigin(Holtburg);

        ResolveResult r = engine.Resolve(origin + new Vector3(103.4f, 101f, GroundZ + 2.8f), 0xA9B40100u, new Vector3(0.8f, 0f, 0f), Step);
        (r.Outcome, r.CellId, r.Position.Z).Should().Be((ResolveOutcome.Moved, 0xA9B40101u, GroundZ + 3f), $"{frame}: {r}");
    }

    /// <summary>
    /// A cottage's door on its landblock's east (or north) edge: a mover leaving through it lands on the next
    /// landblock's terrain (its own height, its outdoor cell); with that landblock not loaded the move is refused as
    /// unloaded ahead, and at the world's east edge as its edge.
    /// </summary>
    [Theory]
    [InlineData("global", true)]
    [InlineData("centred", true)]
    [InlineData("global", false)]
    [InlineData("centred", false)]
    public void A_door_on_the_landblock_edge_leads_onto_the_next_landblock_or_is_refused_as_unloaded_or_the_worlds_edge(string frame, bool east)
    {
        uint next = east ? 0xAAB4FFFFu : 0xA9B5FFFFu;
        CellSurface cottage = DoorCell(0xA9B40100u, east);
        Vector3 delta = east ? new Vector3(0.5f, 0f, 0f) : new Vector3(0f, 0.5f, 0f);

        PhysicsEngine engine = Engine(frame);
        engine.AddLandblock(Holtburg, FlatTerrain(GroundZ), [cottage]);
        Vector3 start = engine.GetLandblockOrigin(Holtburg) + (east ? new Vector3(191.8f, 98f, GroundZ) : new Vector3(98f, 191.8f, GroundZ));

        ResolveResult unloaded = engine.Resolve(start, 0xA9B40100u, delta, Step);
        (unloaded.Outcome, unloaded.Position).Should().Be((ResolveOutcome.UnloadedAhead, start), $"{frame}: {unloaded}");

        engine.AddLandblock(next, FlatTerrain(GroundZ + 0.3f, next), []);
        ResolveResult outside = engine.Resolve(start, 0xA9B40100u, delta, Step);
        outside.Outcome.Should().Be(ResolveOutcome.Moved, $"{frame}: {outside}");
        (outside.CellId >> 16).Should().Be(next >> 16, $"{frame}: on the next landblock: {outside}");
        outside.CellId.Should().Be((next & 0xFFFF0000u) | (east ? 0x0005u : 0x0021u), $"{frame}: its outdoor cell at local {(east ? "(0.3, 98)" : "(98, 0.3)")}: {outside}");
        Vector3.Distance(outside.Position, start + (delta with { Z = 0.3f })).Should().BeLessThan(0.01f, $"{frame}: on its terrain, 0.3 m higher: {outside}");
        outside.Position.Z.Should().Be(GroundZ + 0.3f, $"{frame}: {outside}");

        if (east)
        {
            var edge = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(0xFE10FFFFu);
            edge.AddLandblock(0xFE10FFFFu, FlatTerrain(GroundZ, 0xFE10FFFFu), [DoorCell(0xFE100100u, east: true)]);
            Vector3 atEdge = edge.GetLandblockOrigin(0xFE10FFFFu) + new Vector3(191.8f, 98f, GroundZ);
            ResolveResult off = edge.Resolve(atEdge, 0xFE100100u, delta, Step);
            (off.Outcome, off.Position).Should().Be((ResolveOutcome.EdgeOfWorld, atEdge), $"{frame}: {off}");
        }
    }

    /// <summary>
    /// A room (0x0101) whose only portals are floor openings far below, away from the move, to two cells beside it
    /// (0x0100, the first cell of the landblock, and 0x0102) whose floors, both at the room's height, overlap east of
    /// it: no doorway is crossed and no opening is under the end, so the first portal neighbour with a floor under the
    /// end takes the mover, the one listed first in the room's portals when both are equally near the feet.
    /// </summary>
    [Theory]
    [MemberData(nameof(Frames))]
    public void With_no_portal_deciding_the_first_portal_neighbour_with_a_floor_under_the_end_takes_the_mover(string frame)
    {
        foreach (bool firstListedFirst in new[] { true, false })
        {
            Vector3[] low = Square(100f, 100f, 101f, 101f, GroundZ - 10f), lower = Square(101f, 100f, 102f, 101f, GroundZ - 10f);
            var room = new CellBuilder(0xA9B40101u).Floor(100f, 100f, 104f, 104f, GroundZ);
            room = firstListedFirst
                ? room.Portal(0x0100, new Vector3(100.5f, 100.5f, GroundZ), low).Portal(0x0102, new Vector3(101.5f, 100.5f, GroundZ), lower)
                : room.Portal(0x0102, new Vector3(101.5f, 100.5f, GroundZ), lower).Portal(0x0100, new Vector3(100.5f, 100.5f, GroundZ), low);
            CellSurface first = new CellBuilder(0xA9B40100u).Floor(104f, 100f, 108f, 104f, GroundZ).Portal(0x0101, new Vector3(100.5f, 100.5f, GroundZ - 11f), low).Build();
            CellSurface third = new CellBuilder(0xA9B40102u).Floor(104f, 102f, 108f, 106f, GroundZ).Portal(0x0101, new Vector3(101.5f, 100.5f, GroundZ - 11f), lower).Build();
            PhysicsEngine engine = Engine(frame);
            engine.AddLandblock(Holtburg, FlatTerrain(GroundZ - 20f), [first, room.Build(), third]);
            Vector3 start = engine.GetLandblockOrigin(Holtburg) + new Vector3(103f, 103f, GroundZ);

            ResolveResult only = engine.Resolve(start, 0xA9B40101u, new Vector3(2f, -2f, 0f), Step);
            (only.Outcome, only.CellId, only.Position.Z).Should().Be((ResolveOutcome.Moved, 0xA9B40100u, GroundZ), $"{frame}: over the first cell's floor alone: {only}");
            ResolveResult both = engine.Resolve(start, 0xA9B40101u, new Vector3(2f, 0f, 0f), Step);
            uint expected = firstListedFirst ? 0xA9B40100u : 0xA9B40102u;
            (both.Outcome, both.CellId, both.Position.Z).Should().Be((ResolveOutcome.Moved, expected, GroundZ), $"{frame}: over both floors, the first listed: {both}");
        }
    }

    /// <summary>
    /// A low cellar (floor 94 m) under a room (floor 95 m) with an opening in its ceiling: a mover with its feet between
    /// them stepping out from under the opening over the cellar's floor, beside which the room's floor is, lands on the
    /// one nearer its feet, and on the cellar's own floor when both are equally near (0.5 m).
    /// </summary>
    [Theory]
    [MemberData(nameof(Frames))]
    public void Under_an_opening_the_floor_above_beside_it_wins_when_nearer_the_feet_and_the_cells_own_floor_on_a_tie(string frame)
    {
        Vector3[] opening = Square(100f, 100f, 104f, 102f, GroundZ + 1f);
        CellSurface cellar = new CellBuilder(0xA9B40100u).Floor(94f, 98f, 110f, 104f, GroundZ)
            .Portal(0x0101, new Vector3(102f, 101f, GroundZ + 0.5f), opening).Build();
        CellSurface room = new CellBuilder(0xA9B40101u).Floor(104f, 98f, 110f, 104f, GroundZ + 1f).Floor(94f, 98f, 100f, 104f, GroundZ + 1f)
            .Portal(0x0100, new Vector3(102f, 101f, GroundZ + 2f), opening).Build();
        PhysicsEngine engine = Engine(frame);
        engine.AddLandblock(Holtburg, FlatTerrain(GroundZ - 20f), [cellar, room]);
        Vector3 origin = engine.GetLandblockOrigin(Holtburg);

        ResolveResult tie = engine.Resolve(origin + new Vector3(103.5f, 101f, GroundZ + 0.5f), 0xA9B40100u, new Vector3(1f, 0f, 0f), Step);
        (tie.Outcome, tie.CellId, tie.Position.Z).Should().Be((ResolveOutcome.Moved, 0xA9B40100u, GroundZ), $"{frame}: both 0.5 m from the feet: {tie}");
        ResolveResult above = engine.Resolve(origin + new Vector3(103.5f, 101f, GroundZ + 0.75f), 0xA9B40100u, new Vector3(1f, 0f, 0f), Step);
        (above.Outcome, above.CellId, above.Position.Z).Should().Be((ResolveOutcome.Moved, 0xA9B40101u, GroundZ + 1f), $"{frame}: the room's floor nearer: {above}");
    }

    /// <summary>A 4 m deep room against the landblock's east (or north) edge, with a 2 m door in the edge to the outdoors.</summary>
    private static CellSurface DoorCell(uint id, bool east)
    {
        var inside = east ? new Vector3(190f, 98f, GroundZ + 1f) : new Vector3(98f, 190f, GroundZ + 1f);
        return east
            ? new CellBuilder(id).Floor(188f, 96f, 192f, 100f, GroundZ).Portal(0xFFFF, inside, Wall(192f, 97f, 192f, 99f, GroundZ, GroundZ + 2.5f)).Build()
            : new CellBuilder(id).Floor(96f, 188f, 100f, 192f, GroundZ).Portal(0xFFFF, inside, Wall(97f, 192f, 99f, 192f, GroundZ, GroundZ + 2.5f)).Build();
    }
}
