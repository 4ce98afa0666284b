using System.Numerics;
using AcDream.Core.Physics;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// The closed-form sweep of a body's disc seen from above (<c>BodySweep</c>) against one segment, one polygon cut to
/// the band and a cell's list of walls: a wall from (0, 0) to (10, 0) unless said, a disc of contact radius 0.5 m
/// whose rounding sink is 20 µm (its graze 0.49988 m). Times are checked against the same contact solved in double.
/// </summary>
[Trait("Mutation", "BodySweep")]
public class BodySweepClosedFormTests
{
    private const float Radius = 0.5f;
    private static readonly Vector2 A = new(0f, 0f), B = new(10f, 0f);

    private static BodyMove Move(Vector2 p, Vector2 d, float zLow = 0f, float zHigh = 2f) => BodyMove.Of(p, d, Radius, 2e-5f, zLow, zHigh);

    private static WallHit Segment(Vector2 p, Vector2 d, Vector2 a, Vector2 b, float widen = 0f)
    {
        var hit = WallHit.None;
        BodySweep.SweepSegment(Move(p, d), a, b, widen, ref hit);
        return hit;
    }

    private static WallHit Segment(Vector2 p, Vector2 d) => Segment(p, d, A, B);

    /// <summary>The first fraction of p → p + d at which the centre is <paramref name="r"/> from <paramref name="c"/>, in double.</summary>
    private static double CircleTime(Vector2 p, Vector2 d, Vector2 c, double r)
    {
        double mx = p.X - c.X, my = p.Y - c.Y, a = (d.X * (double)d.X) + (d.Y * (double)d.Y);
        double b = (mx * d.X) + (my * d.Y), cc = (mx * mx) + (my * my) - (r * r);
        return (-b - Math.Sqrt((b * b) - (a * cc))) / a;
    }

    [Fact]
    public void A_disc_overlapping_the_wall_beside_it_and_moving_into_it_is_stopped_at_once_with_the_overlap()
    {
        WallHit hit = Segment(new Vector2(5f, 0.3f), new Vector2(0f, -1f));
        (hit.T, hit.Normal, hit.Outward).Should().Be((0f, Vector2.UnitY, Vector2.UnitY));
        hit.Depth.Should().Be(Radius - MathF.Sqrt(0.3f * 0.3f), "the contact radius less the distance");
    }

    [Fact]
    public void A_disc_overlapping_the_wall_and_moving_away_or_along_it_is_free_but_keeps_its_overlap()
    {
        WallHit away = Segment(new Vector2(5f, 0.3f), new Vector2(0f, 1f));
        (away.T, away.Outward).Should().Be((1f, Vector2.UnitY));
        away.Depth.Should().BeApproximately(0.2f, 1e-6f);

        // Along it, towards it by 1e-6 of the move (below the parallel tolerance, 1e-5): free.
        Segment(new Vector2(5f, 0.3f), new Vector2(1f, -1e-6f)).T.Should().Be(1f);

        // Towards it by 2e-5 of the move: stopped.
        Segment(new Vector2(5f, 0.3f), new Vector2(1f, -2e-5f)).T.Should().Be(0f);
        // The tolerance is a fraction of the move's length: a move of 0.1 m towards it by 2e-5 of its length is stopped,
        // by 1e-6 is free.
        Segment(new Vector2(5f, 0.3f), new Vector2(0.1f, -2e-6f)).T.Should().Be(0f);
        Segment(new Vector2(5f, 0.3f), new Vector2(0.1f, -1e-7f)).T.Should().Be(1f);
    }

    [Fact]
    public void A_disc_overlapping_a_cylinder_wider_than_a_metre_keeps_the_overlap_of_their_radii()
    {
        // A cylinder of radius 1.5 (the segment from (0, 0) to itself, widened): the disc's centre 1.9 m from its axis,
        // moving away, overlaps it by 0.5 + 1.5 − 1.9.
        WallHit hit = Segment(new Vector2(0f, 1.9f), new Vector2(0f, 1f), A, A, widen: 1.5f);
        hit.T.Should().Be(1f);
        hit.Depth.Should().BeApproximately(0.1f, 1e-6f);
        hit.Outward.Should().Be(Vector2.UnitY);
    }

    [Fact]
    public void A_disc_within_the_contact_tolerance_of_the_wall_is_stopped_at_once_with_no_overlap()
    {
        WallHit hit = Segment(new Vector2(5f, 0.50005f), new Vector2(0f, -1f));
        (hit.T, hit.Normal, hit.Depth).Should().Be((0f, Vector2.UnitY, 0f));

        // Just beyond the tolerance (0.5001 m): met where it comes to the contact radius.
        WallHit farther = Segment(new Vector2(5f, 0.5003f), new Vector2(0f, -1f));
        farther.T.Should().BeApproximately(0.0003f, 1e-6f);
        farther.Normal.Should().Be(Vector2.UnitY);
    }

    [Fact]
    public void A_disc_centred_on_the_wall_takes_the_side_it_comes_from()
    {
        // On the wall's middle, moving north: its normal points south, against the move, which it stops.
        WallHit middle = Segment(new Vector2(5f, 0f), new Vector2(0f, 1f));
        (middle.T, middle.Normal, middle.Depth, middle.Outward).Should().Be((0f, -Vector2.UnitY, Radius, -Vector2.UnitY));

        // On the wall's middle, moving north-east: still the wall's own normal, not the move's.
        WallHit slanting = Segment(new Vector2(5f, 0f), new Vector2(1f, 1f));
        (slanting.T, slanting.Normal, slanting.Outward).Should().Be((0f, -Vector2.UnitY, -Vector2.UnitY));

        // On the wall's middle, moving along it: free, and its overlap out of the wall's north side (its normal's own
        // sign when the move takes no side).
        WallHit along = Segment(new Vector2(5f, 0f), new Vector2(1f, 0f));
        (along.T, along.Depth, along.Outward).Should().Be((1f, Radius, Vector2.UnitY));

        // On the wall's end: the same, beside it although at its end.
        WallHit end = Segment(new Vector2(0f, 0f), new Vector2(0f, 1f));
        (end.T, end.Normal, end.Depth, end.Outward).Should().Be((0f, -Vector2.UnitY, Radius, -Vector2.UnitY));
    }

    [Fact]
    public void A_disc_on_a_cylinders_axis_is_pushed_against_its_move_or_along_x_when_still()
    {
        // A cylinder of radius 0.4 at (3, 3): a segment of no length widened by its radius.
        Vector2 axis = new(3f, 3f);
        WallHit moving = Segment(axis, new Vector2(0f, 2f), axis, axis, 0.4f);
        (moving.T, moving.Normal, moving.Depth, moving.Outward).Should().Be((0f, -Vector2.UnitY, Radius + 0.4f, -Vector2.UnitY));

        WallHit still = Segment(axis, Vector2.Zero, axis, axis, 0.4f);
        (still.T, still.Depth, still.Outward).Should().Be((1f, Radius + 0.4f, Vector2.UnitX));
    }

    [Theory]
    [InlineData(2f)]
    [InlineData(-2f)]
    public void A_disc_coming_square_at_the_wall_is_met_at_its_contact_radius_on_its_side(float y)
    {
        WallHit hit = Segment(new Vector2(5f, y), new Vector2(0f, -2f * y));
        hit.T.Should().Be(0.375f, "1.5 m of 4 m");
        hit.Normal.Should().Be(new Vector2(0f, MathF.Sign(y)));
        hit.Depth.Should().Be(0f);
    }

    [Fact]
    public void A_disc_coming_slantwise_at_the_wall_is_met_on_the_offset_line_where_it_is_beside_it()
    {
        // From (2, 3) to (4, -1): the offset line y = 0.5 is reached at t = 2.5 / 4 = 0.625, x = 3.25.
        WallHit hit = Segment(new Vector2(2f, 3f), new Vector2(2f, -4f));
        hit.T.Should().BeApproximately(0.625f, 1e-6f);
        hit.Normal.Should().Be(Vector2.UnitY);

        // The same line reached beyond the wall's end (x 10.25 at the line): met on the end's circle instead.
        WallHit beyond = Segment(new Vector2(9f, 3f), new Vector2(2f, -4f));
        beyond.T.Should().BeApproximately((float)CircleTime(new Vector2(9f, 3f), new Vector2(2f, -4f), B, Radius), 2e-6f);
        beyond.Normal.X.Should().BeGreaterThan(0f, $"from the end B outwards: {beyond.Normal}");
    }

    [Fact]
    public void A_disc_coming_along_the_walls_line_is_met_on_its_ends_circle()
    {
        // From 3 m before A along the wall's line: met 0.5 m before A, at t = 2.5 / 4.
        WallHit hit = Segment(new Vector2(-3f, 0f), new Vector2(4f, 0f));
        (hit.T, hit.Normal).Should().Be((0.625f, -Vector2.UnitX));

        // From beyond B the other way, and short of it: B's circle; not reached.
        WallHit back = Segment(new Vector2(13f, 0f), new Vector2(-4f, 0f));
        (back.T, back.Normal).Should().Be((0.625f, Vector2.UnitX));
        Segment(new Vector2(-3f, 0f), new Vector2(2f, 0f)).T.Should().Be(1f);
    }

    [Fact]
    public void A_disc_passing_an_end_off_the_walls_line_is_met_on_its_circle_at_the_double_precision_time()
    {
        // Parallel to the wall, 0.3 m to its side, beyond A: the end's circle.
        Vector2 p = new(-3f, 0.3f), d = new(4f, 0f);
        WallHit hit = Segment(p, d);
        hit.T.Should().BeApproximately((float)CircleTime(p, d, A, Radius), 1e-6f);
        hit.Normal.X.Should().BeApproximately(-0.8f, 1e-5f);
        hit.Normal.Y.Should().BeApproximately(0.6f, 1e-5f);
    }

    [Fact]
    public void A_disc_in_the_skin_beside_an_end_moving_past_it_and_inwards_is_met_on_its_circle_not_at_once()
    {
        // 0.50005 m from A, beyond it (in the contact tolerance, not beside the wall), moving mostly sideways and a
        // little towards A: met where its centre comes to the contact radius of A, a little later, not at t = 0.
        Vector2 p = new(-0.50005f, 0f), d = new(0.1f, 1f);
        WallHit hit = Segment(p, d);
        double t = CircleTime(p, d, A, Radius);
        t.Should().BeGreaterThan(4e-4);
        hit.T.Should().BeApproximately((float)t, 1e-6f);
        hit.Depth.Should().Be(0f);
    }

    [Fact]
    public void A_disc_sunk_into_an_ends_circle_is_met_at_its_depth_or_at_the_sink_when_in_the_skin()
    {
        // 0.3 m from A beyond it, moving at it: overlapping by 0.2 m (the end's normal) and stopped at once.
        WallHit deep = Segment(new Vector2(-0.3f, 0f), new Vector2(1f, 0f));
        deep.T.Should().BeApproximately(0f, 1e-6f);
        (deep.Normal, deep.Outward).Should().Be((-Vector2.UnitX, -Vector2.UnitX));
        deep.Depth.Should().BeApproximately(0.2f, 1e-6f);

        // 0.49999 m from A: in the skin, deeper than the sink's circle (0.49998 m): met there, 1e-5 of the move on.
        WallHit skin = Segment(new Vector2(-0.49999f, 0f), new Vector2(1f, 0f));
        skin.T.Should().BeApproximately(1e-5f, 2e-7f);
        skin.T.Should().BeGreaterThan(0f);
        skin.Normal.Should().Be(-Vector2.UnitX);

        // The same, moving past A sideways only by the graze: not met.
        Segment(new Vector2(-0.49999f, 0f), new Vector2(0f, 1f)).T.Should().Be(1f);
    }

    [Fact]
    public void A_contact_as_early_as_the_one_so_far_takes_the_normal_first_in_the_fixed_order()
    {
        // Met on A's circle at t = 0.625 with normal (−1, 0); a contact so far at the same time with a normal that comes
        // after it (smaller X) gives way, one that comes before it does not.
        var hit = WallHit.None;
        hit.T = 0.625f;
        hit.Normal = new Vector2(-1f, -0.5f);
        BodySweep.SweepSegment(Move(new Vector2(-3f, 0f), new Vector2(4f, 0f)), A, B, 0f, ref hit);
        (hit.T, hit.Normal).Should().Be((0.625f, -Vector2.UnitX));

        hit.Normal = Vector2.UnitY;
        BodySweep.SweepSegment(Move(new Vector2(-3f, 0f), new Vector2(4f, 0f)), A, B, 0f, ref hit);
        (hit.T, hit.Normal).Should().Be((0.625f, Vector2.UnitY));
    }

    [Fact]
    public void A_disc_of_no_radius_passing_exactly_through_an_end_gives_no_contact_without_a_normal()
    {
        var hit = WallHit.None;
        BodySweep.SweepSegment(BodyMove.Of(new Vector2(-1f, 0f), new Vector2(2f, 0f), 0f, 0f, 0f, 2f), A, A, 0f, ref hit);
        (hit.T, hit.Depth).Should().Be((1f, 0f));
        float.IsNaN(hit.Normal.X).Should().BeFalse();
    }

    /// <summary>A wall triangle in the plane y = 0: (0, 0, 0), (10, 0, 0), (0, 0, 10); its x reach at height z is 10 − z.</summary>
    private static readonly Vector3[] Triangle = [new(0f, 0f, 0f), new(10f, 0f, 0f), new(0f, 0f, 10f)];

    [Theory]
    [InlineData(2f, 4f, -8f, 0.3125f)]   // cut to z 2..4: reaches x 8, met at 8.5
    [InlineData(5f, 20f, -8f, 0.6875f)]  // cut to z 5..10: reaches x 5, met at 5.5
    [InlineData(-5f, 1f, -8f, 0.0625f)]  // cut to z 0..1: reaches x 10, met at 10.5
    [InlineData(0f, 4f, -8f, 0.0625f)]   // its base on the band's foot: reaches x 10
    [InlineData(11f, 12f, -8f, 1f)]      // wholly below the band
    [InlineData(-5f, -1f, -8f, 1f)]      // wholly above it
    public void A_slanted_wall_is_cut_to_the_band_and_met_where_its_cut_reaches(float zLow, float zHigh, float dx, float t)
    {
        foreach (bool reversed in new[] { false, true })
        {
            Vector3[] v = reversed ? [.. Triangle.Reverse()] : Triangle;
            var hit = WallHit.None;
            BodySweep.SweepPolygon(v, new Vector2(0f, 0f), Move(new Vector2(11f, 0f), new Vector2(dx, 0f), zLow, zHigh), ref hit);
            hit.T.Should().BeApproximately(t, 1e-6f, $"band {zLow}..{zHigh}, reversed {reversed}");
            if (t < 1f)
            {
                hit.Normal.Should().Be(Vector2.UnitX);
            }
        }
    }

    [Fact]
    public void A_slanted_wall_in_another_landblocks_frame_is_met_moved_by_its_offset()
    {
        var hit = WallHit.None;
        BodySweep.SweepPolygon(Triangle, new Vector2(-192f, 0f), Move(new Vector2(-181f, 0f), new Vector2(-8f, 0f), 2f, 4f), ref hit);
        hit.T.Should().BeApproximately(0.3125f, 1e-5f);

        // The north neighbour's: moved along Y.
        var north = WallHit.None;
        BodySweep.SweepPolygon(Triangle, new Vector2(0f, 192f), Move(new Vector2(11f, 192f), new Vector2(-8f, 0f), 2f, 4f), ref north);
        north.T.Should().BeApproximately(0.3125f, 1e-5f);

        // Broadside across the face's middle (x 5), which only the edges between the cut's vertices cover.
        var across = WallHit.None;
        BodySweep.SweepPolygon(Triangle, new Vector2(0f, 192f), Move(new Vector2(5f, 189f), new Vector2(0f, 3f), 2f, 4f), ref across);
        across.T.Should().BeApproximately((3f - Radius) / 3f, 1e-5f);
        across.Normal.Should().Be(-Vector2.UnitY);
    }

    /// <summary>
    /// <paramref name="count"/> upright walls 1 m long facing east, in a row along X 2 m apart (wall i from (2i, 0) to
    /// (2i, 1), 0–3 m high), and a move of 2 m west from 1 m east of the last one: met 0.5 m on, at t = 0.25.
    /// </summary>
    private static (CellWalls Walls, BodyMove Move) Row(int count)
    {
        var polygons = new List<(ushort, Vector3[], Vector3)>();
        for (int i = 0; i < count; i++)
        {
            float x = 2f * i;
            polygons.Add(((ushort)i, [new(x, 0f, 0f), new(x, 1f, 0f), new(x, 1f, 3f), new(x, 0f, 3f)], Vector3.UnitX));
        }

        CellWalls walls = CellWalls.Build("row", polygons, [], [], "polygons");
        float last = 2f * (count - 1);
        return (walls, Move(new Vector2(last + 1f, 0.5f), new Vector2(-2f, 0f)));
    }

    private static WallHit Walls(CellWalls walls, BodyMove move, ulong candidates = ulong.MaxValue)
    {
        var hit = WallHit.None;
        Vector2 grow = new(Radius + PhysicsConstants.ContactTolerance);
        Vector2 lo = Vector2.Min(move.P, move.P + move.D) - grow, hi = Vector2.Max(move.P, move.P + move.D) + grow;
        BodySweep.SweepWalls(walls, candidates, Vector2.Zero, new WallBox(lo, hi, move.ZLow, move.ZHigh), in move, ref hit);
        return hit;
    }

    [Theory]
    [InlineData(1)]
    [InlineData(63)]
    [InlineData(64)]
    [InlineData(65)]
    [InlineData(70)]
    public void The_last_of_a_cells_walls_is_met_however_many_it_has(int count)
    {
        (CellWalls walls, BodyMove move) = Row(count);
        WallHit hit = Walls(walls, move);
        (hit.T, hit.Normal).Should().Be((0.25f, Vector2.UnitX), $"{count} walls: met 0.5 m before the last");
    }

    [Fact]
    public void Only_the_walls_named_as_candidates_are_swept_up_to_the_64th()
    {
        (CellWalls walls, BodyMove move) = Row(10);
        Walls(walls, move, ~(1UL << 9)).T.Should().Be(1f, "the wall met is not a candidate");
        Walls(walls, move, 1UL << 9).T.Should().Be(0.25f);

        (CellWalls many, BodyMove past) = Row(65);
        Walls(many, past, 0UL).T.Should().Be(0.25f, "past 64 walls every one is swept");
    }

    [Theory]
    [InlineData(3f, 4f)]    // above the walls' tops
    [InlineData(-2f, 0f)]   // below their feet
    public void Walls_outside_the_band_are_not_met(float zLow, float zHigh)
    {
        (CellWalls walls, BodyMove move) = Row(3);
        Walls(walls, move with { ZLow = zLow, ZHigh = zHigh }).T.Should().Be(1f);
        Walls(walls, move with { ZLow = zLow - 0.5f, ZHigh = zHigh + 0.5f }).T.Should().Be(0.25f, "the band reaching into them");
    }

    [Fact]
    public void A_cylinder_among_a_cells_walls_is_met_at_the_sum_of_the_radii_and_named_as_one()
    {
        CellWalls walls = CellWalls.Build("tree", [], [], [(new Vector3(5f, 5f, 0f), 0.4f, 5f)], "cylinders");
        BodyMove move = Move(new Vector2(1f, 5f), new Vector2(4f, 0f));
        var hit = WallHit.None;
        hit.Current = new WallSource(SurfaceKind.ObjectWall, 7u);
        BodySweep.SweepWalls(walls, Vector2.Zero, new Vector2(0f, 4f), new Vector2(6f, 6f), in move, ref hit);
        hit.T.Should().BeApproximately(3.1f / 4f, 1e-6f, "met with its centre 0.9 m from the axis");
        hit.Normal.Should().Be(-Vector2.UnitX);
        hit.Source.Should().Be(new WallSource(SurfaceKind.Cylinder, 7u));
        hit.Current.Should().Be(new WallSource(SurfaceKind.ObjectWall, 7u), "the owner again after the cylinder");

        var mover = WallHit.None;
        mover.Current = new WallSource(SurfaceKind.Mover, 9u);
        BodySweep.SweepWalls(walls, Vector2.Zero, new Vector2(0f, 4f), new Vector2(6f, 6f), in move, ref mover);
        mover.Source.Should().Be(new WallSource(SurfaceKind.Mover, 9u), "a mover is named as one");
    }
}
