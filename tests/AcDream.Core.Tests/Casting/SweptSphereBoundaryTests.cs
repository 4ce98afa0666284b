using AcDream.Core.Physics;

namespace AcDream.Core.Tests.Casting;

/// <summary>
/// The swept sphere at the exact bounds of its rules, with inputs whose arithmetic is exact in double (dyadic
/// coordinates, radii whose squares sum exactly): the polygon's least area, the face's edge tolerance met exactly, a
/// normal exactly at the floor limit, starts exactly a radius from an edge, a corner and a rim, tangent passes, a ray in a
/// polygon's plane, a cylinder's caps at the start's plane and at the path's end, level passes over caps and past rims,
/// and the bilinear cell at its span's ends, at a tangent and where its quadratic's roots are far apart. Coordinates are
/// relative to the start; each expected contact is worked out by hand.
/// </summary>
[Trait("Mutation", "SweptSphere")]
public class SweptSphereBoundaryTests
{
    private const uint Id = 31;

    private static SweptSphere Polygon(D3[] v, D3 move, double radius)
    {
        var s = new SweptSphere(default, move, radius);
        s.Polygon(v, new ShapeName(SurfaceKind.CellFloor, Id), SurfaceKind.CellCeiling);
        return s;
    }

    private static void ShouldMeet(in SweptSphere s, double t, D3 normal, SurfaceKind kind = SurfaceKind.CellFloor, uint id = Id)
    {
        s.Found.Should().BeTrue($"met nothing");
        s.T.Should().Be(t);
        s.Normal.X.Should().BeApproximately(normal.X, 1e-12, $"normal {s.Normal}");
        s.Normal.Y.Should().BeApproximately(normal.Y, 1e-12, $"normal {s.Normal}");
        s.Normal.Z.Should().BeApproximately(normal.Z, 1e-12, $"normal {s.Normal}");
        s.Kind.Should().Be(kind);
        s.Id.Should().Be(id);
    }

    private static void ShouldMiss(in SweptSphere s)
    {
        s.Found.Should().BeFalse($"met at {s.T} with {s.Normal}");
        s.T.Should().Be(double.PositiveInfinity);
    }

    /// <summary>The rectangle x0..x1, y0..y1 at height z, wound so its normal is up.</summary>
    private static D3[] Rectangle(double x0, double x1, double y0, double y1, double z) =>
        [new(x0, y0, z), new(x1, y0, z), new(x1, y1, z), new(x0, y1, z)];

    [Theory]
    [InlineData(2.0, 1.0, 3.0, 1.0, false)] // the path ends exactly on the near side
    [InlineData(2.0, 1.0, 3.5, 1.0, true)]
    [InlineData(2.0, 0.5, 2.0, 1.0, false)] // the limit scales the path: it ends at 1, the near side
    [InlineData(2.0, 0.5, 2.5, 1.0, true)]
    [InlineData(-2.0, 1.0, -3.0, 1.0, false)]
    [InlineData(-2.0, 1.0, -3.5, 1.0, true)]
    [InlineData(2.0, 1.0, -1.0, 1.0, false)] // behind the start, its far side exactly at the start
    [InlineData(2.0, 1.0, -1.5, 1.0, true)]
    [InlineData(-2.0, 1.0, 1.0, 1.0, false)]
    [InlineData(-2.0, 1.0, 1.5, 1.0, true)]
    [InlineData(2.0, 1.0, 1.0, 0.25, false)] // wholly within the path's stretch
    public void One_axis_of_the_rims_box_pre_check_is_apart_only_beyond_its_bounds(double move, double limit, double centre, double half, bool apart)
    {
        SweptSphere.Apart(move, limit, centre, half).Should().Be(apart);
    }

    [Fact]
    public void A_polygon_whose_Newell_normal_is_1e_12_long_has_no_area_and_one_twice_that_has()
    {
        // A sliver triangle 1 m long and 1e-12 m wide under the start: its Newell normal (twice its area) is (0, 0, 1e-12).
        ShouldMiss(Polygon([new(0, 0, -1), new(1, 0, -1), new(0, 1e-12, -1)], new D3(0, 0, -2), 0));

        // Twice as long: 2e-12, an area: the ray falling on its corner meets its face (the corner within the tolerance).
        ShouldMeet(Polygon([new(0, 0, -1), new(2, 0, -1), new(0, 1e-12, -1)], new D3(0, 0, -2), 0), 0.5, new D3(0, 0, 1));
    }

    [Fact]
    public void A_ray_exactly_the_edge_tolerance_outside_a_face_meets_it()
    {
        // The rectangle's edge on y = 0 (x −1..1), 2 m below; the ray lands at y = −1e-6 exactly (−2e-6 × 0.5).
        ShouldMeet(Polygon(Rectangle(-1, 1, 0, 2, -2), new D3(0, -2e-6, -4), 0), 0.5, new D3(0, 0, 1));

        // Twice that outside: not.
        ShouldMiss(Polygon(Rectangle(-1, 1, 0, 2, -2), new D3(0, -4e-6, -4), 0));
    }

    [Fact]
    public void A_sphere_starting_exactly_its_radius_from_a_polygons_edge_meets_the_edge_not_the_face()
    {
        // The rectangle x 0.5..2.5 at z = −0.375; the start 0.5 m beside its edge x = 0.5 and 0.375 m above its plane:
        // 0.625 m from the edge (0.25 + 0.140625 = 0.390625, exact), a radius of 0.625. Not within the radius: the
        // sweep meets the edge at once, with the edge's normal (−0.5, 0, 0.375)/0.625, moving down.
        ShouldMeet(Polygon(Rectangle(0.5, 2.5, -1, 1, -0.375), new D3(0, 0, -1), 0.625), 0, new D3(-0.8, 0, 0.6));

        // Moving away, or along the edge short of its corner: free.
        ShouldMiss(Polygon(Rectangle(0.5, 2.5, -1, 1, -0.375), new D3(-1, 0, 0), 0.625));
        ShouldMiss(Polygon(Rectangle(0.5, 2.5, -1, 1, -0.375), new D3(0, 0.5, 0), 0.625));

        // Along the edge to its end: the corner (0.5, 1, −0.375), the same 0.625 m off the path's end, is touched there.
        ShouldMeet(Polygon(Rectangle(0.5, 2.5, -1, 1, -0.375), new D3(0, 1, 0), 0.625), 1, new D3(-0.8, 0, 0.6));

        // Moving across the line from the edge to the centre (neither nearer nor farther at first), up and over it: free.
        ShouldMiss(Polygon(Rectangle(0.5, 2.5, -1, 1, -0.375), new D3(0.375, 0, 0.5), 0.625));

        // One metre lower, falling 1 m: the edge is met at the end exactly (0.25 + 0.140625 = 0.625² again).
        ShouldMeet(Polygon(Rectangle(0.5, 2.5, -1, 1, -1.375), new D3(0, 0, -1), 0.625), 1, new D3(-0.8, 0, 0.6));
    }

    [Fact]
    public void A_ray_moving_in_a_polygons_plane_is_free_of_it()
    {
        // A start exactly on a plane is free of it either way: a ray along the plane into the polygon from beside it
        // meets neither its edge nor its corners.
        ShouldMiss(Polygon(Rectangle(1, 3, -1, 1, 0), new D3(2, 0, 0), 0));
        ShouldMiss(Polygon(Rectangle(1, 3, -1, 1, 0), new D3(2, 2, 0), 0));

        // A sphere there meets the edge where its centre is a radius from it.
        ShouldMeet(Polygon(Rectangle(1, 3, -1, 1, 0), new D3(2, 0, 0), 0.5), 0.25, new D3(-1, 0, 0));
    }

    private static SweptSphere Cylinder(D3 move, double radius, double axisX, double axisY, double cylinderRadius, double z0, double z1)
    {
        var s = new SweptSphere(default, move, radius);
        s.Cylinder(axisX, axisY, cylinderRadius, z0, z1, new ShapeName(SurfaceKind.Cylinder, Id));
        return s;
    }

    private static SweptSphere Cell(D3 move, double radius, double x0, double y0, double size, CornerHeights heights)
    {
        var s = new SweptSphere(default, move, radius);
        s.BilinearCell(x0, y0, size, in heights, Id);
        return s;
    }

    [Fact]
    public void A_sphere_moving_level_over_a_cylinders_top_or_under_its_bottom_is_free_of_its_caps()
    {
        // Over the axis, 1 m above the top (or below the bottom), moving level: it never comes down to the cap.
        foreach (double r in new[] { 0.0, 0.25 })
        {
            ShouldMiss(Cylinder(new D3(1, 0, 0), r, 0, 0, 0.5, -3, -1));
            ShouldMiss(Cylinder(new D3(1, 0, 0), r, 0, 0, 0.5, 1, 3));
        }

        // Within the radius of the top's plane (or the bottom's), over the axis, moving level: free of the cap too.
        ShouldMiss(Cylinder(new D3(1, 0, 0), 0.25, 0, 0, 0.5, -3, -0.125));
        ShouldMiss(Cylinder(new D3(1, 0, 0), 0.25, 0, 0, 0.5, 0.125, 3));
    }

    [Fact]
    public void A_start_exactly_on_a_cylinders_cap_plane_moving_into_the_cylinder_is_free_of_the_cap()
    {
        // As on a polygon's plane: the centre on the top's plane (over the axis) moving down, on the bottom's moving up.
        foreach (double r in new[] { 0.0, 0.25 })
        {
            ShouldMiss(Cylinder(new D3(0, 0, -1), r, 0, 0, 0.5, -3, 0));
            ShouldMiss(Cylinder(new D3(0, 0, 1), r, 0, 0, 0.5, 0, 3));
        }

        // A hair above it (or below), the cap is met at once.
        ShouldMeet(Cylinder(new D3(0, 0, -1), 0.25, 0, 0, 0.5, -3, -1.0 / 1024), 0, new D3(0, 0, 1), SurfaceKind.Cylinder);
        ShouldMeet(Cylinder(new D3(0, 0, 1), 0.25, 0, 0, 0.5, 1.0 / 1024, 3), 0, new D3(0, 0, -1), SurfaceKind.Cylinder);
    }

    [Fact]
    public void A_cap_reached_exactly_at_the_end_of_the_path_is_met_there()
    {
        // The top 2 m below, the sphere of 0.25 falling 1.75 m: its centre reaches a radius over the top at the end.
        ShouldMeet(Cylinder(new D3(0.25, 0, -1.75), 0.25, 0, 0, 0.5, -5, -2), 1, new D3(0, 0, 1), SurfaceKind.Cylinder);
        ShouldMeet(Cylinder(new D3(0.25, 0, 1.75), 0.25, 0, 0, 0.5, 2, 5), 1, new D3(0, 0, -1), SurfaceKind.Cylinder);
        ShouldMiss(Cylinder(new D3(0.25, 0, -1.5), 0.25, 0, 0, 0.5, -5, -2));
    }

    [Theory]
    [InlineData(1.0)]
    [InlineData(-1.0)]
    public void A_sphere_moving_level_past_a_rim_just_beyond_the_cap_meets_the_rim(double up)
    {
        // The top's rim 0.1 m below the path (or the bottom's 0.1 m above), the axis 2 m ahead: the centre is a radius
        // (0.25) from the circle (radius 0.5) where its distance from the axis is 0.5 + √(0.25² − 0.1²).
        double z = -0.1 * up, beside = Math.Sqrt((0.25 * 0.25) - (0.1 * 0.1));
        SweptSphere s = Cylinder(new D3(4, 0, 0), 0.25, 2, 0, 0.5, up > 0 ? z - 3 : z, up > 0 ? z : z + 3);
        s.Found.Should().BeTrue();
        s.T.Should().BeApproximately((2 - 0.5 - beside) / 4, 1e-12);
        s.Normal.X.Should().BeApproximately(-beside / 0.25, 1e-9);
        s.Normal.Y.Should().BeApproximately(0, 1e-12);
        s.Normal.Z.Should().BeApproximately(0.1 * up / 0.25, 1e-9);

        // The same across the other axes and the other way.
        SweptSphere back = Cylinder(new D3(0, -4, 0), 0.25, 0, -2, 0.5, up > 0 ? z - 3 : z, up > 0 ? z : z + 3);
        back.T.Should().BeApproximately((2 - 0.5 - beside) / 4, 1e-12);
        back.Normal.Y.Should().BeApproximately(beside / 0.25, 1e-9);
        back.Normal.Z.Should().BeApproximately(0.1 * up / 0.25, 1e-9);
    }

    [Fact]
    public void A_ray_ending_exactly_on_a_cells_edge_below_its_ground_meets_it_at_the_end()
    {
        // The cell from x = 2 (relative) east, its ground at 0; the ray reaches x = 2 at its end, 1 m below the ground,
        // moving down: met at 1, entering.
        ShouldMeet(Cell(new D3(2, 0.5, -1), 0, 2, -1, 4, new CornerHeights(0, 0, 0, 0)), 1, new D3(0, 0, 1), SurfaceKind.Terrain);

        // Below the ground moving level (or up) where it enters: free.
        ShouldMiss(Cell(new D3(4, 0.5, 0), 0, -1, -1, 4, new CornerHeights(0.5, 0.5, 0.5, 0.5)));
    }

    [Fact]
    public void A_ray_meeting_flat_ground_exactly_at_the_end_or_on_the_cells_far_edge_is_met()
    {
        // Ground 2 m below: a ray falling 2 m meets it at the end; one reaching it where it leaves the cell (x = 3, at
        // t 0.5) meets it there.
        ShouldMeet(Cell(new D3(0.5, 0.5, -2), 0, -1, -1, 4, new CornerHeights(-2, -2, -2, -2)), 1, new D3(0, 0, 1), SurfaceKind.Terrain);
        ShouldMeet(Cell(new D3(6, 0.5, -4), 0, -1, -1, 4, new CornerHeights(-2, -2, -2, -2)), 0.5, new D3(0, 0, 1), SurfaceKind.Terrain);
        ShouldMeet(Cell(new D3(0.5, 6, -4), 0, -1, -1, 4, new CornerHeights(-2, -2, -2, -2)), 0.5, new D3(0, 0, 1), SurfaceKind.Terrain);
    }

    [Fact]
    public void A_ray_touching_a_twisted_cell_without_passing_below_it_is_not_met()
    {
        // Over the cell 0..1 with corners SW, SE, NW −0.25 and NE −1.25: h = −0.25 − u·v. Along the diagonal u = v = t
        // the ray's height −t is above h by (t − 0.5)²: it touches the patch at t 0.5 and rises off it.
        ShouldMiss(Cell(new D3(1, 1, -1), 0, 0, 0, 1, new CornerHeights(-0.25, -0.25, -0.25, -1.25)));

        // Falling faster (−1.25 t), it passes below: met where it first comes down to it, t² − 1.25 t + 0.25 = 0 at 0.25.
        ShouldMeet(Cell(new D3(1, 1, -1.25), 0, 0, 0, 1, new CornerHeights(-0.25, -0.25, -0.25, -1.25)), 0.25, new D3(0.25, 0.25, 1) * (1 / Math.Sqrt(1.125)), SurfaceKind.Terrain);
    }

    [Fact]
    public void A_sphere_starting_exactly_its_radius_from_a_polygons_corner_and_moving_at_it_meets_the_corner_at_once()
    {
        // The rectangle x 0.375..2.375, y 0.5..2.5 in the start's plane: its corner (0.375, 0.5) is 0.625 m away
        // (0.140625 + 0.25 = 0.390625, exact), the radius; its edges' lines are nearer, beside their segments.
        ShouldMeet(Polygon(Rectangle(0.375, 2.375, 0.5, 2.5, 0), new D3(0.3, 0.4, 0), 0.625), 0, new D3(-0.6, -0.8, 0));
        ShouldMiss(Polygon(Rectangle(0.375, 2.375, 0.5, 2.5, 0), new D3(-0.3, -0.4, 0), 0.625));

        // Moving up, across the line to the corner (neither nearer nor farther at first): free.
        ShouldMiss(Polygon(Rectangle(0.375, 2.375, 0.5, 2.5, 0), new D3(0, 0, 1), 0.625));
    }

    [Fact]
    public void A_sphere_starting_exactly_its_radius_from_a_rims_circle_is_free_moving_away()
    {
        // The axis 1 m away at (−1, 0), radius 0.5, its top 0.375 m below: the start is (0.5, 0.375) from the circle in
        // (ρ, w), 0.625 m (exact), the radius. Moving away from the axis, or up: free; moving at the axis: met at once.
        foreach (D3 away in new[] { new D3(1, 0, 0), new D3(0, 0, 1) })
        {
            ShouldMiss(Cylinder(away, 0.625, -1, 0, 0.5, -3.375, -0.375));
        }

        ShouldMeet(Cylinder(new D3(-1, 0, 0), 0.625, -1, 0, 0.5, -3.375, -0.375), 0, new D3(0.8, 0, 0.6), SurfaceKind.Cylinder);
    }

    [Fact]
    public void A_sphere_starting_within_a_rims_torus_and_moving_along_the_circle_is_free_of_it()
    {
        // 0.6 m from the axis (radius 0.5), 0.1 m above the top: inside the torus of 0.25; moving along y, across the
        // line from the circle to the centre: neither towards it nor away, free.
        ShouldMiss(Cylinder(new D3(0, 1, 0), 0.25, -0.6, 0, 0.5, -3, -0.1));
    }

    [Fact]
    public void A_sphere_skimming_a_plane_at_exactly_its_radius_touches_the_edge_it_crosses()
    {
        // The rectangle x 1..3 at z = −0.625, the sphere of 0.625 moving level at its height over the plane: it passes
        // over the edge x = 1 exactly a radius from it, and touches it there (t 0.5), with the normal up.
        ShouldMeet(Polygon(Rectangle(1, 3, -1, 1, -0.625), new D3(2, 0, 0), 0.625), 0.5, new D3(0, 0, 1));
    }

    [Fact]
    public void A_sphere_starting_beside_a_cylinder_within_its_rims_torus_below_the_rim_and_moving_up_is_free()
    {
        // 0.6 m from the axis (radius 0.5), 0.1 m below the top: within 0.25 of the top's circle, but beside the side
        // (which decides: moving up, along it, is free of it).
        ShouldMiss(Cylinder(new D3(0, 0, 1), 0.25, -0.6, 0, 0.5, -3, 0.1));
    }

    [Fact]
    public void A_ray_starting_on_a_twisted_cell_and_rising_off_it_is_met_where_the_patch_overtakes_it()
    {
        // Over the cell 0..1 with corners SW, SE, NW 0 and NE 2: h = 2·u·v. Along the diagonal u = v = t the ray rises
        // as t, the patch as 2t²: on it at the start, rising off it (free there), below it again from t 0.5.
        ShouldMeet(Cell(new D3(1, 1, 1), 0, 0, 0, 1, new CornerHeights(0, 0, 0, 2)), 0.5, new D3(-1, -1, 1) * (1 / Math.Sqrt(3)), SurfaceKind.Terrain);
    }

    [Fact]
    public void A_ray_onto_a_twisted_cell_whose_quadratic_has_roots_far_apart_is_met_to_the_last_bits()
    {
        // Corners SW, SE, NW −0.5 and NE −0.5 − 1e-8 (relative): h = −0.5 − 1e-8·u·v, a quadratic whose second root
        // is 1e8 away; the ray along the diagonal falling 1 m meets it near t 0.5. The gap there is zero to the last
        // bits of its terms (a root taken from the difference of nearly equal numbers would be 1e-8 off).
        var heights = new CornerHeights(-0.5, -0.5, -0.5, -0.5 - 1e-8);
        SweptSphere s = Cell(new D3(1, 1, -1), 0, 0, 0, 1, heights);
        s.Found.Should().BeTrue();
        double t = s.T, u = t, v = t;
        double h = (heights.SW * (1 - u) * (1 - v)) + (heights.SE * u * (1 - v)) + (heights.NW * (1 - u) * v) + (heights.NE * u * v);
        (-t - h).Should().BeApproximately(0, 1e-15, $"t {t:R}");
        t.Should().BeApproximately(0.5, 1e-8);

        // Rising into a cell whose patch rises faster (corner NE 2 m above the others): the gap −(t − 1e-9)(t − 0.9) has
        // roots 1e-9 and 0.9; the ray enters the cell at 0.1 above the patch and falls through it at 0.9.
        var steep = new CornerHeights(0.0100000009, 0.0100000009, 0.0100000009, 2.0100000009);
        var move = new D3(1, 0.5, 0.900000001);
        SweptSphere r = Cell(move, 0, 0.1, -0.05, 1, steep);
        r.Found.Should().BeTrue();
        double tr = r.T, ur = (move.X * tr) - 0.1, vr = (move.Y * tr) + 0.05;
        double hr = (steep.SW * (1 - ur) * (1 - vr)) + (steep.SE * ur * (1 - vr)) + (steep.NW * (1 - ur) * vr) + (steep.NE * ur * vr);
        ((move.Z * tr) - hr).Should().BeApproximately(0, 1e-14, $"t {tr:R}");
        tr.Should().BeApproximately(0.9, 1e-8);
    }

    [Fact]
    public void A_polygon_whose_normal_is_exactly_at_the_floor_limit_facing_down_is_named_by_the_kind_facing_down()
    {
        // The triangle (2, 0, 0), (2, 1, 0), (2 + f, 0, g) with f the floor limit (a float, 0.6641741…) and
        // g = 0.7475778972253531: its Newell normal is (g, 0, −f) exactly and 1 long exactly, so its unit normal's Z is
        // −f to the bit: at the limit, named as facing down.
        double f = PhysicsConstants.FloorZ, g = 0.7475778972253531;
        D3[] v = [new(2, 0, 0), new(2, 1, 0), new(2 + f, 0, g)];
        (D3 newell, _) = D3.Newell(v);
        newell.Should().Be(new D3(g, 0, -f));
        newell.Length.Should().Be(1);
        SweptSphere s = Polygon(v, (v[0] + v[1] + v[2]) * (2.0 / 3), 0);
        s.Found.Should().BeTrue();
        s.T.Should().BeApproximately(0.5, 1e-12);
        s.Kind.Should().Be(SurfaceKind.CellCeiling);
    }
}
