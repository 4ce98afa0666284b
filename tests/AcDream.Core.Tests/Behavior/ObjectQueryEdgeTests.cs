using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using AcDream.Core.Tests.Robustness;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// The object queries of a point move at their edges, asked directly of <see cref="ObjectQueries"/> over a
/// landblock built from a few objects on flat ground at 94 m (outdoors: <see cref="ObjectQueries.AmongOutdoors(LandblockEntry, in StepLine, ObjectPass, ref ObjectHit)"/>;
/// inside a cell: <see cref="ObjectQueries.FirstCrossing"/>), and through <see cref="PhysicsEngine.TryGetGround(Vector3, uint, float, out float, out Vector3, out uint)"/>:
/// a move ending exactly on a wall at the object's outermost coordinate; a ramp whose foot is exactly at the step
/// line; an end point exactly on the edge of a floor's bounds (grown by the edge tolerance); floors below, at and
/// level with the ground; and which of two objects is named when a floor rises through the line and a wall is met.
/// Landblock-local metres; every coordinate is exact in float.
/// </summary>
[Trait("Mutation", "ObjectQueries")]
public class ObjectQueryEdgeTests
{
    private const float Ground = 94f;
    private const float H = 94.5f; // feet on the ground plus a step of 0.5 m
    private const uint Outdoors = Holtburg & 0xFFFF0000;

    private static ObjectSurface Object(uint id, params Vector3[][] polygons) =>
        new(ObjectKit.Gfx(id, polygons), ObjectKit.At(Vector3.Zero, 0f), 0);

    /// <summary>A ramp over y 40..44 rising eastward by 1 m over x 40..44, its foot (x 40) at <paramref name="footZ"/>.</summary>
    private static ObjectSurface Ramp(uint id, float footZ, float x0 = 40f) =>
        Object(id, [new Vector3(x0, 40f, footZ), new Vector3(x0 + 4f, 40f, footZ + 1f), new Vector3(x0 + 4f, 44f, footZ + 1f), new Vector3(x0, 44f, footZ)]);

    private static LandblockEntry Land(params ObjectSurface[] objects) => LandblockAssembly.Build(Holtburg, FlatTerrain(Ground), [], objects);

    private static (float T, Vector3 Normal, ObjectSurface? Wall, bool Rises) Outdoor(LandblockEntry entry, Vector2 p0, Vector2 p1, float h = H)
    {
        var hit = ObjectHit.Over(Ground);
        ObjectQueries.AmongOutdoors(entry, new StepLine(p0, p1, h), ObjectPass.Walls, ref hit);
        return (hit.T, hit.Normal, hit.Wall, hit.Rises);
    }

    private static (float T, Vector3 Normal, ObjectSurface? Wall, bool Rises) Inside(ObjectSurface[] objects, Vector2 p0, Vector2 p1, float h = H)
    {
        var hit = ObjectHit.Over(0f);
        ObjectQueries.FirstCrossing(objects, new StepLine(p0, p1, h), ref hit);
        return (hit.T, hit.Normal, hit.Wall, hit.Rises);
    }

    [Theory]
    // The box 40..44 × 40..44 against boxes touching it on each side, and a hair (a float step) beyond each side.
    [InlineData(44f, 41f, 46f, 43f, true)] // east
    [InlineData(44.000004f, 41f, 46f, 43f, false)]
    [InlineData(38f, 41f, 40f, 43f, true)] // west
    [InlineData(38f, 41f, 39.999996f, 43f, false)]
    [InlineData(41f, 44f, 43f, 46f, true)] // north
    [InlineData(41f, 44.000004f, 43f, 46f, false)]
    [InlineData(41f, 38f, 43f, 40f, true)] // south
    [InlineData(41f, 38f, 43f, 39.999996f, false)]
    [InlineData(41f, 41f, 41f, 41f, true)] // a point inside
    [InlineData(44f, 44f, 44f, 44f, true)] // a point on the corner
    [InlineData(45f, 42f, 45f, 42f, false)] // a point east, level with the box
    [InlineData(42f, 45f, 42f, 45f, false)] // a point north, beside it
    [InlineData(30f, 30f, 50f, 50f, true)] // a box holding the whole
    [Trait("Mutation", "WallSet")]
    public void Boxes_seen_from_above_overlap_when_they_share_a_point_and_touching_is_sharing(float loX, float loY, float hiX, float hiY, bool overlaps)
    {
        Boxes.Overlaps(new Vector2(40f, 40f), new Vector2(44f, 44f), new Vector2(loX, loY), new Vector2(hiX, hiY)).Should().Be(overlaps);
    }

    [Theory]
    [InlineData(94.5f, true)]
    [InlineData(94f, false)] // level with the bottom
    [InlineData(96f, false)] // level with the top
    [InlineData(93f, false)]
    [InlineData(97f, false)]
    public void A_height_straddles_an_objects_band_only_strictly_between_its_bottom_and_top(float h, bool straddles)
    {
        ObjectQueries.Straddles(94f, 96f, h).Should().Be(straddles);
    }

    public static TheoryData<string, float, float, float, float, float, float> Walls() => new()
    {
        // A wall alone (its object's bounds are the wall), a move ending exactly on it from each side along each axis:
        // wall from (x0, y0) to (x1, y1), the move from (ax, ay) to the wall's middle.
        { "west face, moving east", 40f, 40f, 40f, 44f, 38f, 42f },
        { "east face, moving west", 40f, 40f, 40f, 44f, 42f, 42f },
        { "south face, moving north", 40f, 40f, 44f, 40f, 42f, 38f },
        { "north face, moving south", 40f, 40f, 44f, 40f, 42f, 42f },
    };

    [Theory]
    [MemberData(nameof(Walls))]
    public void A_move_ending_exactly_on_a_wall_at_its_objects_outermost_coordinate_has_crossed_it(string what, float x0, float y0, float x1, float y1, float ax, float ay)
    {
        ObjectSurface wall = Object(0x01000901, Wall(x0, y0, x1, y1, 93f, 96f));
        var on = new Vector2((x0 + x1) / 2f, (y0 + y1) / 2f);
        var from = new Vector2(ax, ay);
        Vector3 facing = new(Vector2.Normalize(from - on), 0f);

        var outdoor = Outdoor(Land(wall), from, on);
        (outdoor.T, outdoor.Normal, outdoor.Wall, outdoor.Rises).Should().Be((1f, facing, wall, false), $"outdoors, {what}");
        var inside = Inside([wall], from, on);
        (inside.T, inside.Normal, inside.Wall, inside.Rises).Should().Be((1f, facing, wall, false), $"inside a cell, {what}");

        // Starting on it, moving away: it may leave.
        Outdoor(Land(wall), on, from).Wall.Should().BeNull($"outdoors, {what}, leaving");
        Inside([wall], on, from).Wall.Should().BeNull($"inside a cell, {what}, leaving");
    }

    [Fact]
    public void A_ramp_whose_foot_is_exactly_at_the_step_line_is_passed_under_and_one_whose_foot_is_below_it_rises_through_it()
    {
        // A move from x 38 to x 42 at y 42 (the ramp is 94.5 + 0.5 = 95 m there). The ramp is its object's lowest
        // point: as a wall whose bottom is at the line, a floor whose foot is at the line is passed under.
        ObjectSurface atLine = Ramp(0x01000902, H);
        Outdoor(Land(atLine), new(38f, 42f), new(42f, 42f)).Should().Be((2f, Vector3.Zero, (ObjectSurface?)null, false), "outdoors, foot at the line");
        Inside([atLine], new(38f, 42f), new(42f, 42f)).Should().Be((2f, Vector3.Zero, (ObjectSurface?)null, false), "inside a cell, foot at the line");

        // The foot 0.25 m below the line: the plane meets the line at x 41, 3/4 of the move; the normal faces down the slope.
        ObjectSurface below = Ramp(0x01000903, H - 0.25f);
        foreach (var (where, r) in new[] { ("outdoors", Outdoor(Land(below), new(38f, 42f), new(42f, 42f))), ("inside a cell", Inside([below], new(38f, 42f), new(42f, 42f))) })
        {
            (r.Wall, r.Rises, r.Normal).Should().Be((below, true, -Vector3.UnitX), where);
            r.T.Should().BeApproximately(0.75f, 1e-6f, where);
        }
    }

    [Fact]
    public void A_wall_met_before_a_rising_floor_of_another_object_is_a_wall_and_after_it_a_rise()
    {
        // The ramp (foot 0.25 m under the line) rises through it at 3/4 of the move x 38 → 42; a wall across the move
        // at x 39 (1/4) or x 41.5 (7/8), another object listed after the ramp.
        ObjectSurface ramp = Ramp(0x01000904, H - 0.25f);
        ObjectSurface near = Object(0x01000905, Wall(39f, 44f, 39f, 40f, 93f, 96f));
        ObjectSurface far = Object(0x01000906, Wall(41.5f, 44f, 41.5f, 40f, 93f, 96f));
        Vector2 from = new(38f, 42f), to = new(42f, 42f);

        var outdoor = Outdoor(Land(ramp, near), from, to);
        (outdoor.T, outdoor.Wall, outdoor.Rises).Should().Be((0.25f, near, false), "outdoors: the wall at x 39 first");
        var inside = Inside([ramp, near], from, to);
        (inside.T, inside.Wall, inside.Rises).Should().Be((0.25f, near, false), "inside a cell: the wall at x 39 first");

        outdoor = Outdoor(Land(ramp, far), from, to);
        (outdoor.Wall, outdoor.Rises).Should().Be((ramp, true), "outdoors: the rise at x 41 first");
        outdoor.T.Should().BeApproximately(0.75f, 1e-6f);
        inside = Inside([ramp, far], from, to);
        (inside.Wall, inside.Rises).Should().Be((ramp, true), "inside a cell: the rise at x 41 first");
        inside.T.Should().BeApproximately(0.75f, 1e-6f);
    }

    [Fact]
    public void A_wall_met_and_then_an_object_in_reach_but_not_met_leave_the_wall()
    {
        // The wall at x 39 is met at 1/4 of the move; a second wall along the move (y 43, x 38..42), listed after it,
        // is in reach but never crossed: the answer is the first wall, not a rise.
        ObjectSurface near = Object(0x01000907, Wall(39f, 44f, 39f, 40f, 93f, 96f));
        ObjectSurface along = Object(0x01000908, Wall(38f, 43f, 42f, 43f, 93f, 96f));
        Vector2 from = new(38f, 42f), to = new(42f, 42f);
        Outdoor(Land(near, along), from, to).Should().Be((0.25f, -Vector3.UnitX, near, false), "outdoors");
        Inside([near, along], from, to).Should().Be((0.25f, -Vector3.UnitX, near, false), "inside a cell");

        // A rise, then an object in reach not met: still the rise.
        ObjectSurface ramp = Ramp(0x01000909, H - 0.25f);
        var outdoor = Outdoor(Land(ramp, along), from, to);
        (outdoor.Wall, outdoor.Rises).Should().Be((ramp, true), "outdoors, the rise kept");
        var inside = Inside([ramp, along], from, to);
        (inside.Wall, inside.Rises).Should().Be((ramp, true), "inside a cell, the rise kept");
    }

    [Fact]
    public void An_end_point_exactly_on_the_edge_of_a_floors_grown_bounds_stands_on_the_floor()
    {
        // A floor at 94.25 m over x 40..44, y 40..44; its bounds grown by the edge tolerance. An end point exactly on
        // each side of those bounds is within the tolerance of the floor's edge.
        ObjectSurface floor = Object(0x0100090A, Square(40f, 40f, 44f, 44f, 94.25f));
        LandblockEntry land = Land(floor);
        Vector2 min = floor.FloorMin, max = floor.FloorMax;
        foreach (Vector2 p in new Vector2[] { new(min.X, 42f), new(42f, min.Y), new(max.X, 42f), new(42f, max.Y) })
        {
            floor.TryFloorBelow(p.X, p.Y, H, out float z).Should().BeTrue($"{p}: on the floor's edge within the tolerance");
            z.Should().Be(94.25f);
            var hit = ObjectHit.Over(Ground);
            ObjectQueries.AmongOutdoors(land, new StepLine(p, p, H), ObjectPass.Floors, ref hit);
            (hit.GroundZ, hit.Floor).Should().Be((94.25f, floor), $"{p}");
        }
    }

    [Fact]
    public void The_ground_is_the_terrain_under_a_floor_below_or_level_with_it_and_the_first_of_two_level_floors()
    {
        PhysicsEngine engine = new(Holtburg);
        ObjectSurface buried = Object(0x0100090B, Square(40f, 40f, 44f, 44f, 93.5f));
        ObjectSurface level = Object(0x0100090C, Square(50f, 40f, 54f, 44f, Ground));
        ObjectSurface first = Object(0x0100090D, Square(60f, 40f, 64f, 44f, 94.25f));
        ObjectSurface second = Object(0x0100090E, Square(60f, 40f, 64f, 44f, 94.25f));
        ObjectSurface low = Object(0x0100090F, Square(70f, 40f, 74f, 44f, 94.25f));
        ObjectSurface lower = Object(0x01000910, Square(70f, 40f, 74f, 44f, 94.125f));
        engine.AddLandblock(Holtburg, FlatTerrain(Ground), [], [buried, level, first, second, low, lower]);
        Vector3 origin = engine.GetLandblockOrigin(Holtburg);

        (float, uint) GroundAt(float x) =>
            engine.TryGetGround(origin + new Vector3(x, 42f, Ground), Outdoors, 0.5f, out float z, out _, out uint id) ? (z, id) : (float.NaN, 0xFFFFFFFFu);

        GroundAt(42f).Should().Be((Ground, 0u), "a floor under the ground does not lower it");
        GroundAt(52f).Should().Be((Ground, 0u), "a floor level with the ground does not raise it: the terrain");
        GroundAt(62f).Should().Be((94.25f, 0x0100090Du), "two floors at one height: the first listed");
        GroundAt(72f).Should().Be((94.25f, 0x0100090Fu), "a lower floor listed after a higher one does not replace it");
    }

    [Fact]
    public void A_move_beside_a_ramps_side_within_the_edge_tolerance_meets_its_rise_outdoors_and_inside_a_cell()
    {
        // The ramp's south side is y 40; a move at y 40 − 0.0001 (within the floors' edge tolerance, 0.0002 m, outside the
        // object's bounds) from x 38 to x 42: its floor rises through the line at x 41, as a point there stands on it.
        ObjectSurface ramp = Ramp(0x01000911, H - 0.25f);
        float y = 40f - 0.0001f;
        ramp.TryFloorBelow(41.5f, y, 95f, out float z).Should().BeTrue("the end point stands on the ramp within the tolerance");
        z.Should().BeApproximately(94.625f, 1e-5f);
        var outdoor = Outdoor(Land(ramp), new(38f, y), new(42f, y));
        var inside = Inside([ramp], new(38f, y), new(42f, y));
        (outdoor.Wall, outdoor.Rises).Should().Be((ramp, true), "outdoors");
        (inside.Wall, inside.Rises).Should().Be((ramp, true), "inside a cell: as outdoors");
        inside.T.Should().Be(outdoor.T);
    }

    [Theory]
    [InlineData("west", true)]
    [InlineData("east", true)]
    [InlineData("south", false)]
    [InlineData("north", false)]
    public void A_move_exactly_along_the_edge_of_a_ramps_grown_bounds_meets_its_rise(string side, bool northward)
    {
        // A ramp rising northward (for the west and east sides) or eastward (south and north), its foot 0.25 m under the
        // line; the move runs up it exactly along one side of its floors' bounds (grown by the edge tolerance), from 2 m
        // before its foot to 2 m onto it: the plane meets the line 1 m onto it, 3/4 of the move, within the tolerance
        // of the ramp's side.
        ObjectSurface ramp = northward
            ? Object(0x01000912, [new Vector3(40f, 40f, H - 0.25f), new Vector3(44f, 40f, H - 0.25f), new Vector3(44f, 44f, H + 0.75f), new Vector3(40f, 44f, H + 0.75f)])
            : Ramp(0x01000913, H - 0.25f);
        Vector2 min = ramp.FloorMin, max = ramp.FloorMax;
        float along = side switch { "west" => min.X, "east" => max.X, "south" => min.Y, _ => max.Y };
        (Vector2 from, Vector2 to, Vector2 at) = northward
            ? (new Vector2(along, 38f), new Vector2(along, 42f), new Vector2(along, 41f))
            : (new Vector2(38f, along), new Vector2(42f, along), new Vector2(41f, along));
        ramp.TryFloorBelow(at.X, at.Y, H, out float z).Should().BeTrue($"{side}: the rise's point is on the ramp within the tolerance");
        z.Should().BeApproximately(H, 1e-5f);
        Vector3 down = northward ? -Vector3.UnitY : -Vector3.UnitX;
        foreach (var (where, r) in new[] { ("outdoors", Outdoor(Land(ramp), from, to)), ("inside a cell", Inside([ramp], from, to)) })
        {
            (r.Wall, r.Rises, r.Normal).Should().Be((ramp, true, down), $"{side}, {where}");
            r.T.Should().BeApproximately(0.75f, 1e-6f, $"{side}, {where}");
        }
    }
}
