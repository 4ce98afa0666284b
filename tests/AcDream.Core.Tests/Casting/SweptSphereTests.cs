using AcDream.Core.Physics;
using FluentAssertions;
using Xunit;

namespace AcDream.Core.Tests.Casting;

/// <summary>
/// The swept sphere on its own, against one shape at a time whose contact is known in closed form: a polygon's face, its
/// edges and corners, a start within the radius, an upright cylinder's side, caps and rims, the bilinear ground, the
/// polynomial roots the rims are found with, and the bookkeeping of the earliest contact (the stretch it is kept in, a
/// tie, a forgotten contact). Coordinates are relative to the start; the expected fractions and normals are worked out
/// by hand in each test.
/// </summary>
[Trait("Mutation", "SweptSphere")]
public class SweptSphereTests
{
    private const double Tight = 1e-12;
    private const uint Id = 77;

    private static readonly D3 Origin = new(0, 0, 0);

    /// <summary>A square of side 2 centred under (or over) the start at height z, wound so its normal is up (or down).</summary>
    private static D3[] Square(double z, bool up = true, double cx = 0, double cy = 0)
    {
        D3[] v = [new(cx - 1, cy - 1, z), new(cx + 1, cy - 1, z), new(cx + 1, cy + 1, z), new(cx - 1, cy + 1, z)];
        if (!up)
        {
            Array.Reverse(v);
        }

        return v;
    }

    private static SweptSphere Polygon(D3[] v, D3 move, double radius, D3 start = default)
    {
        var s = new SweptSphere(start, move, radius);
        s.Polygon(v, new(SurfaceKind.CellFloor, Id), SurfaceKind.CellWall);
        return s;
    }

    private static void ShouldMeet(in SweptSphere s, double t, D3 normal, SurfaceKind kind = SurfaceKind.CellFloor, uint id = Id)
    {
        s.Found.Should().BeTrue();
        s.T.Should().BeApproximately(t, Tight);
        s.Normal.X.Should().BeApproximately(normal.X, 1e-9, $"normal {s.Normal}");
        s.Normal.Y.Should().BeApproximately(normal.Y, 1e-9, $"normal {s.Normal}");
        s.Normal.Z.Should().BeApproximately(normal.Z, 1e-9, $"normal {s.Normal}");
        s.Kind.Should().Be(kind);
        s.Id.Should().Be(id);
    }

    private static void ShouldMiss(in SweptSphere s)
    {
        s.Found.Should().BeFalse($"met at {s.T}");
        s.T.Should().Be(double.PositiveInfinity);
        s.Kind.Should().Be(SurfaceKind.None);
        s.Id.Should().Be(0u);
    }

    [Fact]
    public void A_new_sphere_has_met_nothing_and_its_centre_moves_along_the_segment()
    {
        var s = new SweptSphere(new D3(10, 20, 30), new D3(2, -4, 6), 0.5);
        ShouldMiss(s);
        s.MoveSquared.Should().Be(56);
        s.Radius.Should().Be(0.5);
        s.At(0.25).Should().Be(new D3(10.5, 19, 31.5));
        s.At(0).Should().Be(new D3(10, 20, 30));
    }

    [Theory]
    [InlineData(0.5)]
    [InlineData(0.0)]
    public void A_sphere_falling_onto_a_square_meets_its_face_a_radius_above_it(double r)
    {
        // The square 2 m below, the sphere moving 4 m down: the face is met when the centre is r above it.
        SweptSphere s = Polygon(Square(-2), new D3(0.25, -0.5, -4), r);
        ShouldMeet(s, (2 - r) / 4, new D3(0, 0, 1));

        // Wound the other way (its normal down, a ceiling's): the same contact, named by the kind facing down.
        SweptSphere down = Polygon(Square(-2, up: false), new D3(0.25, -0.5, -4), r);
        ShouldMeet(down, (2 - r) / 4, new D3(0, 0, 1), SurfaceKind.CellWall);

        // From below, rising into it: the normal points down at the sphere.
        SweptSphere rising = Polygon(Square(2), new D3(0.25, -0.5, 4), r);
        ShouldMeet(rising, (2 - r) / 4, new D3(0, 0, -1));
    }

    [Fact]
    public void A_steep_polygon_facing_down_is_named_by_the_kind_facing_down_and_one_facing_up_by_its_kind()
    {
        // A wall tilted so its normal's Z is -0.6 (steeper than a floor facing down) and one whose normal's Z is -0.8.
        foreach ((double nz, SurfaceKind expected, double turn) in new[]
        {
            (-0.6, SurfaceKind.CellFloor, 0.0), (-0.8, SurfaceKind.CellWall, 0.0), (0.8, SurfaceKind.CellFloor, 0.0),
            (-0.6, SurfaceKind.CellFloor, 1.1), (-0.8, SurfaceKind.CellWall, 2.0), (0.8, SurfaceKind.CellFloor, -2.6),
        })
        {
            double h = Math.Sqrt(1 - (nz * nz));
            var n = new D3(h * Math.Cos(turn), h * Math.Sin(turn), nz);
            var u = new D3(-Math.Sin(turn), Math.Cos(turn), 0);
            D3 w = D3.Cross(n, u); // in the plane, with u: (u, w, n) right-handed for a counter-clockwise winding about n
            D3 c = n * -2; // the plane 2 m from the start, the start on its normal's side
            D3[] v = [c - u - w, c + u - w, c + u + w, c - u + w];
            (D3 newell, _) = D3.Newell(v);
            D3.Dot(newell, n).Should().BeGreaterThan(0, "wound about n");
            SweptSphere s = Polygon(v, n * -4, 0.25);
            ShouldMeet(s, 1.75 / 4, n, expected);
        }
    }

    [Fact]
    public void A_polygon_of_no_area_is_met_by_nothing()
    {
        D3[] line = [new(-1, 0, -1), new(0, 0, -1), new(1, 0, -1)];
        ShouldMiss(Polygon(line, new D3(0, 0, -2), 0.5));
        D3[] point = [new(0, 0, -1), new(0, 0, -1), new(0, 0, -1)];
        ShouldMiss(Polygon(point, new D3(0, 0, -2), 0.5));

        // A sliver 1e-7 m wide still has area: met.
        D3[] sliver = [new(-1, 0, -1), new(1, 0, -1), new(1, 1e-7, -1)];
        Polygon(sliver, new D3(0, 0, -2), 0.5).Found.Should().BeTrue();
    }

    [Fact]
    public void A_ray_meets_a_face_within_the_edge_tolerance_of_it_and_misses_it_beyond()
    {
        // The square spans x in -1..1: a ray falling at x = 1 + 0.9e-6 is within the 1e-6 tolerance, at 1 + 1.1e-6 it is not.
        ShouldMeet(Polygon(Square(-2, cx: -1 - 0.9e-6), new D3(0, 0, -4), 0), 0.5, new D3(0, 0, 1));
        ShouldMiss(Polygon(Square(-2, cx: -1 - 1.1e-6), new D3(0, 0, -4), 0));
        ShouldMeet(Polygon(Square(-2, cy: 1 + 0.9e-6), new D3(0, 0, -4), 0), 0.5, new D3(0, 0, 1));
        ShouldMiss(Polygon(Square(-2, cy: 1 + 1.1e-6), new D3(0, 0, -4), 0));
        ShouldMiss(Polygon(Square(-2, up: false, cx: 1 + 1.1e-6), new D3(0, 0, -4), 0));
        ShouldMeet(Polygon(Square(-2, up: false, cx: 1 + 0.9e-6), new D3(0, 0, -4), 0), 0.5, new D3(0, 0, 1), SurfaceKind.CellWall);
    }

    [Fact]
    public void A_ray_meets_nothing_short_of_the_plane_moving_away_from_it_or_along_it()
    {
        ShouldMiss(Polygon(Square(-2), new D3(0, 0, -1.9), 0)); // short of it
        ShouldMeet(Polygon(Square(-2), new D3(0, 0, -2), 0), 1.0, new D3(0, 0, 1)); // reaching it at the end exactly
        ShouldMiss(Polygon(Square(-2), new D3(0, 0, 4), 0)); // away
        ShouldMiss(Polygon(Square(-2), new D3(4, 0, 0), 0)); // along
        ShouldMiss(Polygon(Square(0), new D3(0, 0, 1), 0)); // starting on it, moving up: on the side it moves to
        ShouldMiss(Polygon(Square(0), new D3(0, 0, -1), 0)); // starting on it, moving down
        ShouldMiss(Polygon(Square(0, up: false), new D3(0, 0, 1), 0));
        ShouldMiss(Polygon(Square(0, up: false), new D3(0, 0, -1), 0));
    }

    [Fact]
    public void A_sphere_passing_beside_a_square_meets_its_edge()
    {
        // Centre 0.3 m beyond the edge x = 1, falling: the capsule of the edge is met where 0.3² + dz² = 0.5², dz = 0.4.
        SweptSphere s = Polygon(Square(-2, cx: -1.3), new D3(0, 0, -4), 0.5);
        ShouldMeet(s, 1.6 / 4, new D3(0.6, 0, 0.8));

        // Moving sideways into the edge from beside it (level with the square): met where the centre is 0.5 m from it.
        SweptSphere side = Polygon(Square(0, cx: 2), new D3(2, 0, 0), 0.5);
        ShouldMeet(side, 0.25, new D3(-1, 0, 0));

        // The same the other way (the edge x = −1 of a square at x −3..−1), wound down.
        SweptSphere other = Polygon(Square(0, up: false, cx: -2), new D3(-2, 0, 0), 0.5);
        ShouldMeet(other, 0.25, new D3(1, 0, 0), SurfaceKind.CellWall);

        // Passing 0.6 m beside the edge: nothing.
        ShouldMiss(Polygon(Square(-2, cx: -1.6), new D3(0, 0, -4), 0.5));

        // Moving away from it, or along it, from beside it: nothing.
        ShouldMiss(Polygon(Square(0, cx: 2), new D3(-2, 0, 0), 0.5));
        ShouldMiss(Polygon(Square(-0.3, cx: -1.6), new D3(0, 3, 0), 0.5));
    }

    [Fact]
    public void A_sphere_falling_past_a_corner_meets_the_corner()
    {
        // The corner (1, 1) 0.3 m off in x and y: horizontal distance √0.18; met where 0.18 + dz² = 0.25.
        double dz = Math.Sqrt(0.25 - 0.18);
        SweptSphere s = Polygon(Square(-2, cx: -1.3, cy: -1.3), new D3(0, 0, -4), 0.5);
        ShouldMeet(s, (2 - dz) / 4, new D3(0.6, 0.6, dz / 0.5));

        // Moving at the corner along the diagonal, level with the square: met 0.5 m short of it.
        SweptSphere level = Polygon(Square(0, cx: 2, cy: 2), new D3(2, 2, 0), 0.5);
        double corner = Math.Sqrt(2), stop = (corner - 0.5) / (2 * corner);
        ShouldMeet(level, stop, new D3(-Math.Sqrt(0.5), -Math.Sqrt(0.5), 0));

        // The corner 0.6 m away horizontally: nothing; away from it: nothing.
        ShouldMiss(Polygon(Square(-2, cx: -1.45, cy: -1.45), new D3(0, 0, -4), 0.5));
        ShouldMiss(Polygon(Square(0, cx: 2, cy: 2), new D3(-2, -2, 0), 0.5));
    }

    [Fact]
    public void A_sphere_passing_a_corner_at_exactly_its_radius_touches_it()
    {
        // Level with a square whose corner is 0.5 m beside the path: the edges (one along the path, one across it beyond
        // its end) are not touched, the corner is, where the centre passes it.
        ShouldMeet(Polygon(Square(0, cx: 2, cy: -1.5), new D3(2, 0, 0), 0.5), 0.5, new D3(0, 1, 0));
        ShouldMeet(Polygon(Square(0, cx: 2, cy: -1.5), new D3(1, 0, 0), 0.5), 1.0, new D3(0, 1, 0));
        ShouldMiss(Polygon(Square(0, cx: 2, cy: -1.5), new D3(0.999, 0, 0), 0.5));
        ShouldMiss(Polygon(Square(0, cx: 2, cy: -1.50001), new D3(2, 0, 0), 0.5));
    }

    [Fact]
    public void A_corner_or_edge_met_after_the_end_or_behind_an_earlier_contact_is_not_kept()
    {
        // The edge would be met at 0.4 of a 4 m fall: a fall of 1.5 m ends short of it.
        ShouldMiss(Polygon(Square(-2, cx: -1.3), new D3(0, 0, -1.5), 0.5));
        ShouldMeet(Polygon(Square(-2, cx: -1.3), new D3(0, 0, -1.6), 0.5), 1.0, new D3(0.6, 0, 0.8));

        // The corner would be met at (2 − dz)/4: a fall ending just short of it meets nothing.
        double dz = Math.Sqrt(0.25 - 0.18);
        ShouldMiss(Polygon(Square(-2, cx: -1.3, cy: -1.3), new D3(0, 0, -(2 - dz) * 0.999), 0.5));

        // A contact kept at 0.1 is not replaced by the later edge or corner.
        var s = new SweptSphere(Origin, new D3(0, 0, -4), 0.5);
        s.Stop(0.1, new D3(0, 1, 0), new(SurfaceKind.Terrain, 5));
        s.Polygon(Square(-2, cx: -1.3), new(SurfaceKind.CellFloor, Id), SurfaceKind.CellWall);
        s.Polygon(Square(-2, cx: -1.3, cy: -1.3), new(SurfaceKind.CellFloor, Id), SurfaceKind.CellWall);
        ShouldMeet(s, 0.1, new D3(0, 1, 0), SurfaceKind.Terrain, 5);
    }

    [Fact]
    public void The_edge_is_met_on_the_segment_only_and_the_corner_answers_beyond_its_end()
    {
        // A triangle whose edge x = −0.3 (relative) runs from y = −2.2 to −0.2, 2 m below: falling 0.3 m beside its line
        // and 0.2 m beyond its end, the line would be met at dz = 0.4; the segment is not, the corner (−0.3, −0.2) is.
        D3[] tri = [new(-0.3, -2.2, -2), new(-0.3, -0.2, -2), new(-1.3, -1.2, -2)];
        double dz = Math.Sqrt(0.25 - 0.13);
        ShouldMeet(Polygon(tri, new D3(0, 0, -4), 0.5), (2 - dz) / 4, new D3(0.3 / 0.5, 0.2 / 0.5, dz / 0.5));

        // Beyond its other end the same, by the other corner.
        D3[] flipped = [new(-0.3, 2.2, -2), new(-1.3, 1.2, -2), new(-0.3, 0.2, -2)];
        ShouldMeet(Polygon(flipped, new D3(0, 0, -4), 0.5), (2 - dz) / 4, new D3(0.3 / 0.5, -0.2 / 0.5, dz / 0.5));
    }

    [Fact]
    public void A_sphere_moving_along_an_edges_line_from_beyond_its_end_meets_the_corner()
    {
        // The start 0.2 m above the line of the square's edge x = 1 and 0.6 m beyond its corner (1, 1), moving along the
        // line towards it: the corner is met where (0.6 − t)² + 0.2² = 0.5².
        double t = 0.6 - Math.Sqrt(0.21);
        ShouldMeet(Polygon(Square(-0.2, cx: -1, cy: -1.6), new D3(0, -1, 0), 0.5), t, new D3(0, Math.Sqrt(0.21) / 0.5, 0.2 / 0.5));
        ShouldMeet(Polygon(Square(-0.2, up: false, cx: -1, cy: -1.6), new D3(0, -1, 0), 0.5), t, new D3(0, Math.Sqrt(0.21) / 0.5, 0.2 / 0.5), SurfaceKind.CellWall);
    }

    [Fact]
    public void A_sphere_starting_within_its_radius_of_a_face_is_met_at_once_moving_in_and_is_free_moving_out_or_along()
    {
        // 0.3 m above the square's middle, radius 0.5.
        ShouldMeet(Polygon(Square(-0.3), new D3(0, 0, -1), 0.5), 0, new D3(0, 0, 1));
        ShouldMeet(Polygon(Square(-0.3, up: false), new D3(0.1, 0, -1), 0.5), 0, new D3(0, 0, 1), SurfaceKind.CellWall);
        ShouldMeet(Polygon(Square(0.3), new D3(0, 0, 1), 0.5), 0, new D3(0, 0, -1));
        ShouldMiss(Polygon(Square(-0.3), new D3(0, 0, 1), 0.5));
        ShouldMiss(Polygon(Square(-0.3), new D3(1, 0, 0), 0.5));
        ShouldMiss(Polygon(Square(0.3), new D3(0, 0, -1), 0.5));

        // On the plane itself: free whichever way it moves (it is on the side it moves to).
        ShouldMiss(Polygon(Square(0), new D3(0, 0, -1), 0.5));
        ShouldMiss(Polygon(Square(0), new D3(0, 0, 1), 0.5));
        ShouldMiss(Polygon(Square(0), new D3(1, 0, 0), 0.5));
    }

    [Fact]
    public void A_sphere_starting_within_its_radius_of_an_edge_is_met_at_once_moving_into_the_plane_and_free_moving_away()
    {
        // The start 0.2 m beyond the edge x = 1 and 0.3 m above the plane: √0.13 ≈ 0.36 m from the edge, inside r = 0.5.
        ShouldMeet(Polygon(Square(-0.3, cx: -1.2), new D3(0, 0, -1), 0.5), 0, new D3(0, 0, 1));
        ShouldMiss(Polygon(Square(-0.3, cx: -1.2), new D3(1, 0, 0), 0.5));
        ShouldMiss(Polygon(Square(-0.3, cx: -1.2), new D3(0, 0, 1), 0.5));

        // The same within √(0.2² + 0.2² + 0.3²) of the corner (1, 1).
        ShouldMeet(Polygon(Square(-0.3, cx: -1.2, cy: -1.2), new D3(0, 0, -1), 0.5), 0, new D3(0, 0, 1));
        ShouldMiss(Polygon(Square(-0.3, cx: -1.2, cy: -1.2), new D3(1, 1, 0), 0.5));

        // 0.45 m beyond the edge and 0.3 m above: √0.2925 ≈ 0.54 m, outside the radius: the edge is swept and met where
        // 0.45² + dz² = 0.25, falling 1 m.
        double dz = Math.Sqrt(0.25 - (0.45 * 0.45));
        ShouldMeet(Polygon(Square(-0.3, cx: -1.45), new D3(0, 0, -1), 0.5), 0.3 - dz, new D3(0.45 / 0.5, 0, dz / 0.5));
    }

    [Fact]
    public void Shapes_met_at_the_same_fraction_keep_the_first_one_tested()
    {
        var s = new SweptSphere(Origin, new D3(0, 0, -4), 0.5);
        s.Polygon(Square(-2), new(SurfaceKind.CellFloor, 1), SurfaceKind.CellWall);
        s.Polygon(Square(-2), new(SurfaceKind.ObjectFloor, 2), SurfaceKind.ObjectFloor);
        ShouldMeet(s, 0.375, new D3(0, 0, 1), SurfaceKind.CellFloor, 1);

        // A nearer one replaces it.
        s.Polygon(Square(-1.9), new(SurfaceKind.ObjectFloor, 3), SurfaceKind.ObjectFloor);
        ShouldMeet(s, 1.4 / 4, new D3(0, 0, 1), SurfaceKind.ObjectFloor, 3);

        // A farther one does not.
        s.Polygon(Square(-1.95), new(SurfaceKind.Terrain, 4), SurfaceKind.Terrain);
        s.Id.Should().Be(3u);
    }

    [Fact]
    public void Within_keeps_contacts_in_its_stretch_only_until_Everywhere_and_Forget_drops_what_was_kept()
    {
        var s = new SweptSphere(Origin, new D3(0, 0, -4), 0.5);
        s.Within(0.4, 1);
        s.Polygon(Square(-2), new(SurfaceKind.CellFloor, Id), SurfaceKind.CellWall); // at 0.375: before the stretch
        ShouldMiss(s);
        s.Within(0, 0.37);
        s.Polygon(Square(-2), new(SurfaceKind.CellFloor, Id), SurfaceKind.CellWall); // after it
        ShouldMiss(s);
        s.Within(0.375, 0.375);
        s.Polygon(Square(-2), new(SurfaceKind.CellFloor, Id), SurfaceKind.CellWall); // its bounds are in it
        ShouldMeet(s, 0.375, new D3(0, 0, 1));

        s.Forget();
        ShouldMiss(s);
        s.Everywhere();
        s.Polygon(Square(-2.5), new(SurfaceKind.CellFloor, Id), SurfaceKind.CellWall);
        ShouldMeet(s, 0.5, new D3(0, 0, 1));

        // A stretch reaching past the end is cut at the end.
        var past = new SweptSphere(Origin, new D3(0, 0, -1), 0);
        past.Within(0.5, 3);
        past.Stop(1.5, new D3(0, 0, 1), new(SurfaceKind.None, 0));
        ShouldMiss(past);
        past.Stop(1.0, new D3(0, 0, 1), new(SurfaceKind.CellWall, 9));
        ShouldMeet(past, 1.0, new D3(0, 0, 1), SurfaceKind.CellWall, 9);
    }

    [Fact]
    public void Stop_ends_the_cast_only_before_the_contact_kept_and_never_before_the_start()
    {
        var s = new SweptSphere(Origin, new D3(1, 0, 0), 0.1);
        s.Stop(0.6, new D3(-1, 0, 0), new(SurfaceKind.CellWall, 3));
        ShouldMeet(s, 0.6, new D3(-1, 0, 0), SurfaceKind.CellWall, 3);
        s.Stop(0.6, new D3(0, 1, 0), new(SurfaceKind.None, 4));
        s.Id.Should().Be(3u, "a tie keeps the first");
        s.Stop(0.7, new D3(0, 1, 0), new(SurfaceKind.None, 4));
        s.Id.Should().Be(3u);
        s.Stop(0.2, new D3(0, 1, 0), new(SurfaceKind.None, 4));
        ShouldMeet(s, 0.2, new D3(0, 1, 0), SurfaceKind.None, 4);

        // A fraction below 0 within the stretch kept (a stretch starting before the start) is kept as 0.
        var early = new SweptSphere(Origin, new D3(1, 0, 0), 0.1);
        early.Within(-1, 1);
        early.Stop(-0.5, new D3(-1, 0, 0), new(SurfaceKind.CellWall, 6));
        early.T.Should().Be(0);
        early.Found.Should().BeTrue();
    }

    [Fact]
    public void A_sphere_moving_at_a_cylinder_meets_its_side_at_the_sum_of_the_radii()
    {
        // Axis 2 m ahead, radius 0.5, z −1..1: the sphere of 0.25 stops with its centre 0.75 m short of the axis.
        var s = new SweptSphere(Origin, new D3(4, 0, 0), 0.25);
        s.Cylinder(2, 0, 0.5, -1, 1, new(SurfaceKind.Cylinder, 8));
        ShouldMeet(s, 1.25 / 4, new D3(-1, 0, 0), SurfaceKind.Cylinder, 8);

        // Off-centre: the axis 0.3 m to the side; the centre meets the side where (x − 2)² + 0.3² = 0.75².
        var off = new SweptSphere(Origin, new D3(4, 0, 0), 0.25);
        off.Cylinder(2, 0.3, 0.5, -1, 1, new(SurfaceKind.Cylinder, 8));
        double x = 2 - Math.Sqrt((0.75 * 0.75) - 0.09);
        ShouldMeet(off, x / 4, new D3(x - 2, -0.3, 0) * (1 / 0.75), SurfaceKind.Cylinder, 8);

        // A ray (radius 0) meets the side itself.
        var ray = new SweptSphere(Origin, new D3(4, 0, 0), 0);
        ray.Cylinder(2, 0, 0.5, -1, 1, new(SurfaceKind.Cylinder, 8));
        ShouldMeet(ray, 1.5 / 4, new D3(-1, 0, 0), SurfaceKind.Cylinder, 8);

        // The side's Z span: the centre at the contact at z = 0.9 within −1..1 is met; 1.1 is not (nor the cap or rim: a
        // ray has none); exactly at the top it is.
        foreach ((double z, bool met) in new[] { (0.9, true), (1.1, false), (1.0, true), (-1.0, true), (-1.1, false) })
        {
            var level = new SweptSphere(Origin, new D3(4, 0, 0), 0);
            level.Cylinder(2, 0, 0.5, -1 - z, 1 - z, new(SurfaceKind.Cylinder, 8));
            level.Found.Should().Be(met, $"z {z}");
        }

        // Rising as it goes: the contact's height is the move's Z at that fraction (0.375 · 4 = 1.5 m up: above a top at 1).
        var rising = new SweptSphere(Origin, new D3(4, 0, 4), 0);
        rising.Cylinder(2, 0, 0.5, -1, 1, new(SurfaceKind.Cylinder, 8));
        ShouldMiss(rising);
        var rising2 = new SweptSphere(Origin, new D3(4, 0, 4), 0);
        rising2.Cylinder(2, 0, 0.5, -1, 2, new(SurfaceKind.Cylinder, 8));
        ShouldMeet(rising2, 0.375, new D3(-1, 0, 0), SurfaceKind.Cylinder, 8);
    }

    [Fact]
    public void A_sphere_passing_a_cylinder_at_exactly_the_sum_of_the_radii_touches_its_side()
    {
        var s = new SweptSphere(Origin, new D3(4, 0, 0), 0.25);
        s.Cylinder(2, 0.75, 0.5, -1, 1, new(SurfaceKind.Cylinder, 8));
        ShouldMeet(s, 0.5, new D3(0, -1, 0), SurfaceKind.Cylinder, 8);
        var past = new SweptSphere(Origin, new D3(4, 0, 0), 0.25);
        past.Cylinder(2, 0.75 + 1e-9, 0.5, -1, 1, new(SurfaceKind.Cylinder, 8));
        ShouldMiss(past);
    }

    [Fact]
    public void A_sphere_within_reach_of_a_cylinders_side_moving_along_its_axis_is_free_of_it()
    {
        foreach (double dz in new[] { 1.0, -1.0 })
        {
            var s = new SweptSphere(Origin, new D3(0, 0, dz), 0.25);
            s.Cylinder(0.6, 0, 0.5, -5, 5, new(SurfaceKind.Cylinder, 8));
            ShouldMiss(s);
        }
    }

    [Fact]
    public void A_sphere_moving_obliquely_at_a_cylinder_meets_its_side_facing_it()
    {
        // The axis 3 m along the move (4, 3, 0)/5: the centre stops 0.75 m short of it, at 2.25 of 5 m.
        var s = new SweptSphere(Origin, new D3(4, 3, 0), 0.25);
        s.Cylinder(2.4, 1.8, 0.5, -1, 1, new(SurfaceKind.Cylinder, 8));
        ShouldMeet(s, 0.45, new D3(-0.8, -0.6, 0), SurfaceKind.Cylinder, 8);
        var back = new SweptSphere(Origin, new D3(-4, 3, 0), 0.25);
        back.Cylinder(-2.4, 1.8, 0.5, -1, 1, new(SurfaceKind.Cylinder, 8));
        ShouldMeet(back, 0.45, new D3(0.8, -0.6, 0), SurfaceKind.Cylinder, 8);
    }

    [Fact]
    public void A_sphere_misses_a_cylinder_it_passes_moves_away_from_or_stops_short_of()
    {
        var past = new SweptSphere(Origin, new D3(4, 0, 0), 0.25);
        past.Cylinder(2, 0.8, 0.5, -1, 1, new(SurfaceKind.Cylinder, 8)); // 0.8 m beside: beyond 0.75
        ShouldMiss(past);
        var away = new SweptSphere(Origin, new D3(-4, 0, 0), 0.25);
        away.Cylinder(2, 0, 0.5, -1, 1, new(SurfaceKind.Cylinder, 8));
        ShouldMiss(away);
        var shortOf = new SweptSphere(Origin, new D3(1.2, 0, 0), 0.25);
        shortOf.Cylinder(2, 0, 0.5, -1, 1, new(SurfaceKind.Cylinder, 8));
        ShouldMiss(shortOf);
        var reaching = new SweptSphere(Origin, new D3(1.25, 0, 0), 0.25);
        reaching.Cylinder(2, 0, 0.5, -1, 1, new(SurfaceKind.Cylinder, 8));
        ShouldMeet(reaching, 1.0, new D3(-1, 0, 0), SurfaceKind.Cylinder, 8);
        var vertical = new SweptSphere(Origin, new D3(0, 0, 4), 0.25);
        vertical.Cylinder(2, 0, 0.5, -1, 5, new(SurfaceKind.Cylinder, 8)); // beside it, rising: never nearer
        ShouldMiss(vertical);
    }

    [Fact]
    public void A_sphere_starting_within_reach_of_a_cylinders_axis_is_met_at_once_moving_in_and_free_moving_out()
    {
        var inward = new SweptSphere(Origin, new D3(1, 0, 0), 0.25);
        inward.Cylinder(0.6, 0, 0.5, -1, 1, new(SurfaceKind.Cylinder, 8));
        ShouldMeet(inward, 0, new D3(-1, 0, 0), SurfaceKind.Cylinder, 8);
        var outward = new SweptSphere(Origin, new D3(-1, 0, 0), 0.25);
        outward.Cylinder(0.6, 0, 0.5, -1, 1, new(SurfaceKind.Cylinder, 8));
        ShouldMiss(outward);

        // Within reach but above the top, moving in level: not the side (its Z span), nor the cap (not approaching it).
        var above = new SweptSphere(Origin, new D3(1, 0, 0), 0.25);
        above.Cylinder(0.6, 0, 0.5, -3, -1.3, new(SurfaceKind.Cylinder, 8));
        ShouldMiss(above);
    }

    [Fact]
    public void A_sphere_falling_onto_a_cylinder_meets_its_top_and_one_rising_meets_its_bottom()
    {
        var fall = new SweptSphere(Origin, new D3(0.2, 0.1, -4), 0.25);
        fall.Cylinder(0, 0, 0.5, -5, -2, new(SurfaceKind.Cylinder, 8));
        ShouldMeet(fall, 1.75 / 4, new D3(0, 0, 1), SurfaceKind.Cylinder, 8);

        var rise = new SweptSphere(Origin, new D3(0.2, 0.1, 4), 0.25);
        rise.Cylinder(0, 0, 0.5, 2, 5, new(SurfaceKind.Cylinder, 8));
        ShouldMeet(rise, 1.75 / 4, new D3(0, 0, -1), SurfaceKind.Cylinder, 8);

        // A ray meets the top itself.
        var ray = new SweptSphere(Origin, new D3(0, 0, -4), 0);
        ray.Cylinder(0.3, 0, 0.5, -5, -2, new(SurfaceKind.Cylinder, 8));
        ShouldMeet(ray, 0.5, new D3(0, 0, 1), SurfaceKind.Cylinder, 8);

        // Falling to land at the cap's edge: the point under the centre 0.5 m from the axis is on it, 0.5 + 1e-9 is not.
        var edge = new SweptSphere(Origin, new D3(0, 0, -4), 0);
        edge.Cylinder(0.5, 0, 0.5, -5, -2, new(SurfaceKind.Cylinder, 8));
        ShouldMeet(edge, 0.5, new D3(0, 0, 1), SurfaceKind.Cylinder, 8);
        var beyond = new SweptSphere(Origin, new D3(0, 0, -4), 0);
        beyond.Cylinder(0, 0.5 + 1e-9, 0.5, -5, -2, new(SurfaceKind.Cylinder, 8));
        ShouldMiss(beyond);

        // Short of the top, or moving away from it, or below the bottom moving down: nothing.
        var shortOf = new SweptSphere(Origin, new D3(0, 0, -1.7), 0.25);
        shortOf.Cylinder(0, 0, 0.5, -5, -2, new(SurfaceKind.Cylinder, 8));
        ShouldMiss(shortOf);
        var up = new SweptSphere(Origin, new D3(0, 0, 4), 0.25);
        up.Cylinder(0, 0, 0.5, -5, -2, new(SurfaceKind.Cylinder, 8));
        ShouldMiss(up);
        var down = new SweptSphere(Origin, new D3(0, 0, -4), 0.25);
        down.Cylinder(0, 0, 0.5, 2, 5, new(SurfaceKind.Cylinder, 8));
        ShouldMiss(down);

        // Within the radius of the top already, over it, moving down: met at once with the cap's normal.
        var onTop = new SweptSphere(Origin, new D3(0, 0, -1), 0.25);
        onTop.Cylinder(0, 0, 0.5, -3, -0.1, new(SurfaceKind.Cylinder, 8));
        ShouldMeet(onTop, 0, new D3(0, 0, 1), SurfaceKind.Cylinder, 8);
        var underBottom = new SweptSphere(Origin, new D3(0, 0, 1), 0.25);
        underBottom.Cylinder(0, 0, 0.5, 0.1, 3, new(SurfaceKind.Cylinder, 8));
        ShouldMeet(underBottom, 0, new D3(0, 0, -1), SurfaceKind.Cylinder, 8);
    }

    [Fact]
    public void A_sphere_falling_past_a_cylinders_top_edge_meets_its_rim()
    {
        // The centre 0.6 m from the axis (radius 0.5): over the torus about the top's circle, 0.1 m out; met where
        // 0.1² + w² = 0.25².
        double w = Math.Sqrt((0.25 * 0.25) - (0.1 * 0.1));
        var s = new SweptSphere(Origin, new D3(0, 0, -4), 0.25);
        s.Cylinder(-0.6, 0, 0.5, -5, -2, new(SurfaceKind.Cylinder, 8));
        ShouldMeet(s, (2 - w) / 4, new D3(0.1 / 0.25, 0, w / 0.25), SurfaceKind.Cylinder, 8);

        // Rising past the bottom's.
        var r = new SweptSphere(Origin, new D3(0, 0, 4), 0.25);
        r.Cylinder(0, 0.6, 0.5, 2, 5, new(SurfaceKind.Cylinder, 8));
        ShouldMeet(r, (2 - w) / 4, new D3(0, -0.1 / 0.25, -w / 0.25), SurfaceKind.Cylinder, 8);

        // Oblique, at the rim from above and outside: the contact's centre is a radius from the circle.
        var oblique = new SweptSphere(Origin, new D3(1.5, 0.2, -1.5), 0.25);
        oblique.Cylinder(1.5, 0, 0.5, -4, -1.1, new(SurfaceKind.Cylinder, 8));
        oblique.Found.Should().BeTrue();
        D3 c = oblique.Move * oblique.T;
        double rho = Math.Sqrt(((c.X - 1.5) * (c.X - 1.5)) + (c.Y * c.Y));
        double distance = Math.Sqrt(((rho - 0.5) * (rho - 0.5)) + ((c.Z + 1.1) * (c.Z + 1.1)));
        distance.Should().BeApproximately(0.25, 1e-9);
        (c.Z + 1.1).Should().BeGreaterThan(0);
        rho.Should().BeGreaterThan(0.5);
        oblique.Normal.Z.Should().BeApproximately((c.Z + 1.1) / 0.25, 1e-9);

        // 0.8 m from the axis: beyond the torus (0.75): nothing. Short of the rim: nothing.
        var past = new SweptSphere(Origin, new D3(0, 0, -4), 0.25);
        past.Cylinder(-0.8, 0, 0.5, -5, -2, new(SurfaceKind.Cylinder, 8));
        ShouldMiss(past);
        var shortOf = new SweptSphere(Origin, new D3(0, 0, -(2 - w) * 0.99), 0.25);
        shortOf.Cylinder(-0.6, 0, 0.5, -5, -2, new(SurfaceKind.Cylinder, 8));
        ShouldMiss(shortOf);
    }

    [Theory]
    [InlineData(1.5, 0.4, 1.5, 0.9, -1.5, -1.1)]
    [InlineData(-1.2, 0.9, -1.4, 0.5, -1.2, -1.0)]
    [InlineData(0.3, -1.4, 0.6, -1.3, -1.3, -0.9)]
    [InlineData(1.5, 0.4, 1.5, 0.9, 1.5, 1.1)]
    [InlineData(-1.2, 0.9, -1.4, 0.5, 1.2, 1.0)]
    public void A_sphere_moving_obliquely_past_a_cylinders_rim_meets_it_a_radius_from_the_circle(double ax, double ay, double mx, double my, double mz, double rimZ)
    {
        // rimZ < 0: the top's rim below the start (the cylinder below it); > 0: the bottom's above it.
        const double rc = 0.5, r = 0.25;
        bool top = rimZ < 0;
        var s = new SweptSphere(Origin, new D3(mx, my, mz), r);
        s.Cylinder(ax, ay, rc, top ? rimZ - 3 : rimZ, top ? rimZ : rimZ + 3, new(SurfaceKind.Cylinder, 8));
        s.Found.Should().BeTrue();
        s.Kind.Should().Be(SurfaceKind.Cylinder);
        D3 c = s.Move * s.T;
        double hx = c.X - ax, hy = c.Y - ay, rho = Math.Sqrt((hx * hx) + (hy * hy));
        var nearest = new D3(ax + (hx * rc / rho), ay + (hy * rc / rho), rimZ);
        D3 away = c - nearest;
        away.Length.Should().BeApproximately(r, 1e-9, $"the centre {c} is a radius from the circle");
        rho.Should().BeGreaterThan(rc, "beside the side");
        ((c.Z - rimZ) * (top ? 1 : -1)).Should().BeGreaterThan(0, "beyond the cap");
        s.Normal.X.Should().BeApproximately(away.X / r, 1e-7);
        s.Normal.Y.Should().BeApproximately(away.Y / r, 1e-7);
        s.Normal.Z.Should().BeApproximately(away.Z / r, 1e-7);

        // Just before it, the centre is farther than the radius from the circle.
        D3 before = s.Move * (s.T - 1e-7);
        double bx = before.X - ax, by = before.Y - ay, brho = Math.Sqrt((bx * bx) + (by * by));
        Math.Sqrt(((brho - rc) * (brho - rc)) + ((before.Z - rimZ) * (before.Z - rimZ))).Should().BeGreaterThan(r);
    }

    [Fact]
    public void A_sphere_starting_within_the_rims_torus_is_met_at_once_moving_towards_the_circle_and_free_otherwise()
    {
        // 0.6 m from the axis, 0.1 m above the top: 0.1·√2 from the circle, inside r = 0.25.
        var down = new SweptSphere(Origin, new D3(0, 0, -1), 0.25);
        down.Cylinder(-0.6, 0, 0.5, -3, -0.1, new(SurfaceKind.Cylinder, 8));
        ShouldMeet(down, 0, new D3(Math.Sqrt(0.5), 0, Math.Sqrt(0.5)), SurfaceKind.Cylinder, 8);
        var up = new SweptSphere(Origin, new D3(0, 0, 1), 0.25);
        up.Cylinder(-0.6, 0, 0.5, -3, -0.1, new(SurfaceKind.Cylinder, 8));
        ShouldMiss(up);
        var outward = new SweptSphere(Origin, new D3(1, 0, 0), 0.25);
        outward.Cylinder(-0.6, 0, 0.5, -3, -0.1, new(SurfaceKind.Cylinder, 8));
        ShouldMiss(outward);

        // Off the axes: the axis at (−0.36, −0.48), 0.6 m away; 0.1 m above the top.
        var diagonal = new SweptSphere(Origin, new D3(0, 0, -1), 0.25);
        diagonal.Cylinder(-0.36, -0.48, 0.5, -3, -0.1, new(SurfaceKind.Cylinder, 8));
        ShouldMeet(diagonal, 0, new D3(0.06, 0.08, 0.1) * (1 / Math.Sqrt(0.02)), SurfaceKind.Cylinder, 8);

        // The bottom's: 0.1 m below it, rising.
        var rise = new SweptSphere(Origin, new D3(0, 0, 1), 0.25);
        rise.Cylinder(-0.6, 0, 0.5, 0.1, 3, new(SurfaceKind.Cylinder, 8));
        ShouldMeet(rise, 0, new D3(Math.Sqrt(0.5), 0, -Math.Sqrt(0.5)), SurfaceKind.Cylinder, 8);

        // Within the torus but below the top's circle, outside the side (beside it), moving in: the side answers, not the rim.
        var beside = new SweptSphere(Origin, new D3(-1, 0, 0), 0.25);
        beside.Cylinder(-0.6, 0, 0.5, -3, 0.1, new(SurfaceKind.Cylinder, 8));
        ShouldMeet(beside, 0, new D3(1, 0, 0), SurfaceKind.Cylinder, 8);
    }

    [Fact]
    public void Roots_finds_every_real_root_in_the_interval_ascending()
    {
        // (t − 0.2)(t − 0.5)(t − 0.7)(t − 0.9), expanded.
        double[] c = Expand(0.2, 0.5, 0.7, 0.9);
        Span<double> roots = stackalloc double[6];
        int n = SweptSphere.Roots(c, 0, 1, roots);
        n.Should().Be(4);
        roots[0].Should().BeApproximately(0.2, 1e-12);
        roots[1].Should().BeApproximately(0.5, 1e-12);
        roots[2].Should().BeApproximately(0.7, 1e-12);
        roots[3].Should().BeApproximately(0.9, 1e-12);

        // Only those within the interval, its ends included.
        SweptSphere.Roots(c, 0.3, 0.8, roots).Should().Be(2);
        roots[0].Should().BeApproximately(0.5, 1e-12);
        roots[1].Should().BeApproximately(0.7, 1e-12);
        double[] ends = Expand(0.25, 0.5, 0.75, 2);
        SweptSphere.Roots(ends, 0.25, 0.75, roots).Should().Be(3);
        roots[0].Should().Be(0.25);
        roots[1].Should().BeApproximately(0.5, 1e-12);
        roots[2].Should().Be(0.75);

        // Fewer room than roots: as many as fit, the first.
        Span<double> two = stackalloc double[2];
        SweptSphere.Roots(c, 0, 1, two).Should().Be(2);
        two[0].Should().BeApproximately(0.2, 1e-12);
        two[1].Should().BeApproximately(0.5, 1e-12);

        // No room left for a root at the end of the interval: not written.
        Span<double> one = stackalloc double[1];
        SweptSphere.Roots(Expand(0.25, 0.5), 0, 0.5, one).Should().Be(1);
        one[0].Should().BeApproximately(0.25, 1e-12);
        SweptSphere.Roots(Expand(0.25, 0.5), 0, 0.5, roots).Should().Be(2);
        roots[1].Should().Be(0.5);

        // A cubic and a quadratic with roots outside: none.
        SweptSphere.Roots(Expand(-1, 2, 3), 0, 1, roots).Should().Be(0);
        SweptSphere.Roots([1, 0, 1], 0, 1, roots).Should().Be(0); // t² + 1
    }

    [Fact]
    public void Roots_of_a_line_and_of_double_roots_are_found_once()
    {
        Span<double> roots = stackalloc double[6];
        SweptSphere.Roots([-0.3, 1], 0, 1, roots).Should().Be(1);
        roots[0].Should().Be(0.3);
        SweptSphere.Roots([-1.5, 1], 0, 1, roots).Should().Be(0);
        SweptSphere.Roots([0.5, 1], 0, 1, roots).Should().Be(0);
        SweptSphere.Roots([1, 0], 0, 1, roots).Should().Be(0); // constant: none
        SweptSphere.Roots([0, 1], 0, 1, roots).Should().Be(1); // at the start
        roots[0].Should().Be(0);
        SweptSphere.Roots([-1, 1], 0, 1, roots).Should().Be(1); // at the end
        roots[0].Should().Be(1);

        // (t − 0.5)²: a double root, found once (the derivative's root where the polynomial is 0).
        SweptSphere.Roots([0.25, -1, 1], 0, 1, roots).Should().Be(1);
        roots[0].Should().Be(0.5);

        // A double root at either end of the interval: once.
        SweptSphere.Roots([1, -2, 1], 0, 1, roots).Should().Be(1); // (t − 1)²
        roots[0].Should().Be(1);
        SweptSphere.Roots([0, 0, 1], 0, 1, roots).Should().Be(1); // t²
        roots[0].Should().Be(0);

        // (t − 0.5)² (t − 0.75): the single root (a double root whose turn is not found exactly on it is a graze).
        int n = SweptSphere.Roots(Expand(0.5, 0.5, 0.75), 0, 1, roots);
        roots[n - 1].Should().BeApproximately(0.75, 1e-12);
        n.Should().BeOneOf(1, 2);

        // A root at 0 of a quartic that is zero at the start: listed once.
        n = SweptSphere.Roots(Expand(0, 0.4, 0.6, 3), 0, 1, roots);
        n.Should().Be(3);
        roots[0].Should().Be(0);
        roots[1].Should().BeApproximately(0.4, 1e-12);
        roots[2].Should().BeApproximately(0.6, 1e-12);

        // A root the bisection lands on exactly: that root, not its neighbour.
        SweptSphere.Roots([-0.25, 0, 1], 0, 1, roots).Should().Be(1);
        roots[0].Should().Be(0.5);
        SweptSphere.Roots([0.25, 0, -1], 0, 1, roots).Should().Be(1);
        roots[0].Should().Be(0.5);

        // A quadratic falling through zero and one rising through it, with a non-trivial leading term.
        n = SweptSphere.Roots([-0.06, -0.1, 1], 0, 1, roots); // (t − 0.3)(t + 0.2)
        n.Should().Be(1);
        roots[0].Should().BeApproximately(0.3, 1e-15);
        n = SweptSphere.Roots([0.06, 0.1, -1], 0, 1, roots);
        n.Should().Be(1);
        roots[0].Should().BeApproximately(0.3, 1e-15);
    }

    [Fact]
    public void Roots_are_bisected_to_the_last_bit()
    {
        // t − 1/3 and 3t − 1 have their root at the double nearest 1/3 (or one step from it); the cubic's at the cube root.
        Span<double> roots = stackalloc double[6];
        SweptSphere.Roots([-1.0 / 3, 0, 0, 1], -1, 1, roots).Should().Be(1); // t³ = 1/3
        double cube = Math.Cbrt(1.0 / 3);
        roots[0].Should().BeApproximately(cube, 4e-16);
        SweptSphere.Roots([-2, 0, 1], 0, 2, roots).Should().Be(1); // t² = 2
        roots[0].Should().BeApproximately(Math.Sqrt(2), 4.5e-16);
        SweptSphere.Roots([-2, 0, 1], 0.5, 100, roots).Should().Be(1);
        roots[0].Should().BeApproximately(Math.Sqrt(2), 4.5e-16);
        SweptSphere.Roots([2, 0, -1], -100, -0.5, roots).Should().Be(1);
        roots[0].Should().BeApproximately(-Math.Sqrt(2), 4.5e-16);
    }

    /// <summary>The coefficients (constant first) of the monic polynomial with these roots.</summary>
    private static double[] Expand(params double[] roots)
    {
        double[] c = [1];
        foreach (double r in roots)
        {
            var next = new double[c.Length + 1];
            for (int i = 0; i < c.Length; i++)
            {
                next[i + 1] += c[i];
                next[i] -= r * c[i];
            }

            c = next;
        }

        return c;
    }

    [Fact]
    public void A_sphere_falling_onto_a_flat_cell_of_ground_meets_it_a_radius_above_with_its_lowest_point()
    {
        // The cell's south-west corner 1 m west and south of the start, side 24 m, 2 m below.
        var s = new SweptSphere(Origin, new D3(0.5, 0.25, -4), 0.25);
        s.BilinearCell(-1, -1, 24, new(-2, -2, -2, -2), 0x1234);
        ShouldMeet(s, 1.75 / 4, new D3(0, 0, 1), SurfaceKind.Terrain, 0x1234);

        // A ray.
        var ray = new SweptSphere(Origin, new D3(0.5, 0.25, -4), 0);
        ray.BilinearCell(-1, -1, 24, new(-2, -2, -2, -2), 0x1234);
        ShouldMeet(ray, 0.5, new D3(0, 0, 1), SurfaceKind.Terrain, 0x1234);

        // Outside the cell (east of it, north of it, west, south): nothing.
        foreach ((double x0, double y0) in new[] { (-30.0, -1.0), (-1.0, -30.0), (1.0, -1.0), (-1.0, 1.0) })
        {
            var outside = new SweptSphere(Origin, new D3(0, 0, -4), 0);
            outside.BilinearCell(x0, y0, 24, new(-2, -2, -2, -2), 0x1234);
            ShouldMiss(outside);
        }

        // Short of it, moving up from above it: nothing.
        var shortOf = new SweptSphere(Origin, new D3(0, 0, -1.5), 0.25);
        shortOf.BilinearCell(-1, -1, 24, new(-2, -2, -2, -2), 0x1234);
        ShouldMiss(shortOf);
        var up = new SweptSphere(Origin, new D3(0, 0, 4), 0.25);
        up.BilinearCell(-1, -1, 24, new(-2, -2, -2, -2), 0x1234);
        ShouldMiss(up);

        // Level over it: nothing.
        var level = new SweptSphere(Origin, new D3(4, 3, 0), 0.25);
        level.BilinearCell(-1, -1, 24, new(-2, -2, -2, -2), 0x1234);
        ShouldMiss(level);
    }

    [Fact]
    public void A_ray_onto_a_sloped_cell_meets_the_plane_with_its_normal()
    {
        // h = −2 + 0.5·(x − x0) over x (the east corners 12 m higher over 24 m), the start 1 m east of the west edge.
        // Falling straight down: h at the start's x is −1.5. Normal: (−0.5, 0, 1)/√1.25.
        var s = new SweptSphere(Origin, new D3(0, 0, -4), 0);
        s.BilinearCell(-1, -1, 24, new(-2, 10, -2, 10), 7);
        ShouldMeet(s, 1.5 / 4, new D3(-0.5, 0, 1) * (1 / Math.Sqrt(1.25)), SurfaceKind.Terrain, 7);

        // North rising: h = −2 + 0.25·(y − y0), at the start −1.75; normal (0, −0.25, 1)/√1.0625.
        var n = new SweptSphere(Origin, new D3(0, 0, -4), 0);
        n.BilinearCell(-1, -1, 24, new(-2, -2, 4, 4), 7);
        ShouldMeet(n, 1.75 / 4, new D3(0, -0.25, 1) * (1 / Math.Sqrt(1.0625)), SurfaceKind.Terrain, 7);

        // Moving east into the rising slope, level: met where −2 + 0.5·(x + 1) = 0 − r... for a ray, x = 3.
        var east = new SweptSphere(Origin, new D3(8, 0, 0), 0);
        east.BilinearCell(-1, -1, 24, new(-2, 10, -2, 10), 7);
        ShouldMeet(east, 3.0 / 8, new D3(-0.5, 0, 1) * (1 / Math.Sqrt(1.25)), SurfaceKind.Terrain, 7);

        // Moving west down the slope, level: never meets it.
        var west = new SweptSphere(Origin, new D3(-0.9, 0, 0), 0);
        west.BilinearCell(-1, -1, 24, new(-2, 10, -2, 10), 7);
        ShouldMiss(west);
    }

    [Fact]
    public void A_ray_onto_a_twisted_cell_meets_the_bilinear_patch_where_its_height_is_the_rays()
    {
        // Corners SW −1, SE −1, NW −1, NE 3 (relative to the start; the cell from (−1, −1) to (3, 3)): h = 4·u·v − 1
        // with u = (x + 1)/4, v = (y + 1)/4, the start 0.75 m over it. Moving diagonally the ray's height above the patch
        // is a quadratic in t: met at its first root where it falls.
        foreach ((D3 move, double r) in new[] { (new D3(1.5, 1.5, -0.5), 0.0), (new D3(1.5, 1.0, -0.6), 0.0), (new D3(1.8, 1.2, -1.0), 0.1), (new D3(-0.8, -0.8, -1.8), 0.0), (new D3(1.5, -0.8, -1.0), 0.05) })
        {
            var s = new SweptSphere(Origin, move, r);
            s.BilinearCell(-1, -1, 4, new(-1, -1, -1, 3), 9);
            s.Found.Should().BeTrue($"{move}");
            D3 c = move * s.T;
            double u = (c.X + 1) / 4, v = (c.Y + 1) / 4;
            double h = -1 + (4 * u * v);
            (c.Z - r).Should().BeApproximately(h, 1e-12, $"{move}: the lowest point on the patch at t {s.T}");

            // Just before it, above the patch.
            D3 before = move * (s.T - 1e-6);
            double ub = (before.X + 1) / 4, vb = (before.Y + 1) / 4;
            (before.Z - r).Should().BeGreaterThan(-1 + (4 * ub * vb), $"{move}");

            // The normal: the patch's gradient.
            double gx = 4 * v / 4, gy = 4 * u / 4, len = Math.Sqrt(1 + (gx * gx) + (gy * gy));
            s.Normal.X.Should().BeApproximately(-gx / len, 1e-9);
            s.Normal.Y.Should().BeApproximately(-gy / len, 1e-9);
            s.Normal.Z.Should().BeApproximately(1 / len, 1e-9);
        }
    }

    [Fact]
    public void A_ray_skimming_a_twisted_cell_that_rises_off_it_is_not_met_where_it_leaves()
    {
        // Corners SW 0, SE 0, NW 0, NE −4 relative (a saddle falling to the north-east), the ray from 1 m above the
        // south-west corner moving north-east and down 0.5 m: h = −4·u·v; z = 1 − 0.5 t at u = v = t: 1 − 0.5t = −4t² has
        // no root in 0..1 (the ray stays above).
        var s = new SweptSphere(Origin, new D3(4, 4, -0.5), 0);
        s.BilinearCell(0, 0, 4, new(-1, -1, -1, -5), 9);
        ShouldMiss(s);

        // A hump (NE +4): h = 4uv − 1 at z = −t... rising out of the patch it entered below: once below, free moving up.
        var under = new SweptSphere(Origin, new D3(4, 4, 4.5), 0);
        under.BilinearCell(0, 0, 4, new(0.5, 0.5, 0.5, 8.5), 9); // the start 0.5 m below the SW corner
        ShouldMiss(under);

        // Starting below the patch and moving down into it: met at once where the ray enters the cell.
        var into = new SweptSphere(Origin, new D3(1, 1, -1), 0);
        into.BilinearCell(0, 0, 4, new(0.5, 0.5, 0.5, 0.5), 9);
        ShouldMeet(into, 0, new D3(0, 0, 1), SurfaceKind.Terrain, 9);

        // Entering the cell from the west below its height, falling: met at the fraction it enters.
        var west = new SweptSphere(Origin, new D3(4, 0.5, -1), 0);
        west.BilinearCell(1, -1, 4, new(0.5, 0.5, 0.5, 0.5), 9);
        ShouldMeet(west, 0.25, new D3(0, 0, 1), SurfaceKind.Terrain, 9);

        // The same with a contact kept earlier: not replaced.
        var earlier = new SweptSphere(Origin, new D3(4, 0.5, -1), 0);
        earlier.Stop(0.1, new D3(1, 0, 0), new(SurfaceKind.CellWall, 1));
        earlier.BilinearCell(1, -1, 4, new(0.5, 0.5, 0.5, 0.5), 9);
        earlier.T.Should().Be(0.1);
        earlier.Kind.Should().Be(SurfaceKind.CellWall);

        // Entering at exactly its height, moving down: met at entry; moving up: free.
        var atHeight = new SweptSphere(Origin, new D3(4, 0.5, -1), 0);
        atHeight.BilinearCell(1, -1, 4, new(-0.25, -0.25, -0.25, -0.25), 9);
        ShouldMeet(atHeight, 0.25, new D3(0, 0, 1), SurfaceKind.Terrain, 9);
        var atHeightUp = new SweptSphere(Origin, new D3(4, 0.5, 1), 0);
        atHeightUp.BilinearCell(1, -1, 4, new(0.25, 0.25, 0.25, 0.25), 9);
        ShouldMiss(atHeightUp);
    }

    [Fact]
    public void A_ray_leaving_the_cell_before_it_comes_down_to_the_ground_is_not_met()
    {
        // The cell from x 0..4; the ray leaves it at x = 4 (t 0.5) and would come down to its plane at t 0.75.
        var s = new SweptSphere(Origin, new D3(8, 0.5, -4), 0);
        s.BilinearCell(-0.001, -1, 4, new(-3, -3, -3, -3), 9);
        ShouldMiss(s);
        var twisted = new SweptSphere(Origin, new D3(8, 0.5, -4), 0);
        twisted.BilinearCell(-0.001, -1, 4, new(-3, -3, -3, -2.9), 9);
        ShouldMiss(twisted);

        // Along a cell edge exactly (the ray on its west line moving north): within the cell's span.
        var edge = new SweptSphere(Origin, new D3(0, 2, -4), 0);
        edge.BilinearCell(0, -1, 4, new(-2, -2, -2, -2), 9);
        ShouldMeet(edge, 0.5, new D3(0, 0, 1), SurfaceKind.Terrain, 9);
        var beside = new SweptSphere(Origin, new D3(0, 2, -4), 0);
        beside.BilinearCell(1e-9, -1, 4, new(-2, -2, -2, -2), 9);
        ShouldMiss(beside);
        var north = new SweptSphere(Origin, new D3(2, 0, -4), 0);
        north.BilinearCell(-1, -4 - 1e-9, 4, new(-2, -2, -2, -2), 9);
        ShouldMiss(north);
        var onNorth = new SweptSphere(Origin, new D3(2, 0, -4), 0);
        onNorth.BilinearCell(-1, -4, 4, new(-2, -2, -2, -2), 9);
        ShouldMeet(onNorth, 0.5, new D3(0, 0, 1), SurfaceKind.Terrain, 9);
    }

    [Fact]
    public void A_ray_through_a_cylinder_of_no_radius_on_its_axis_takes_the_normal_against_its_move()
    {
        var s = new SweptSphere(Origin, new D3(4, 0, 0), 0);
        s.Cylinder(2, 0, 0, -1, 1, new(SurfaceKind.Cylinder, 8));
        ShouldMeet(s, 0.5, new D3(-1, 0, 0), SurfaceKind.Cylinder, 8);
    }
}
