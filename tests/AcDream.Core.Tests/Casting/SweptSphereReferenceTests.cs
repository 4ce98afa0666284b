using AcDream.Core.Physics;
using static AcDream.Testing.CastReference;

namespace AcDream.Core.Tests.Casting;

/// <summary>
/// The swept sphere against the slow reference on random shapes, one at a time: convex polygons in any plane, upright
/// cylinders, bilinear terrain cells; and <see cref="SweptSphere.Roots"/> against polynomials built from their roots.
/// The start is kept clear of the shape (the reference stops any start within the radius at 0, the swept sphere only
/// one moving in), so every contact is swept: the fraction within 1e-7 of the reference's, the normal within 1e-6.
/// </summary>
[Trait("Mutation", "SweptSphere")]
public class SweptSphereReferenceTests
{
    private const double Fraction = 1e-7;
    private const double Direction = 1e-6;

    private static readonly V3 Origin = new(0, 0, 0);

    private static double Uniform(Random random, double lo, double hi) => lo + ((hi - lo) * random.NextDouble());

    private static double RadiusOf(Random random) => random.Next(4) == 0 ? 0 : Uniform(random, 0.05, 0.6);

    private static D3 D(V3 v) => new(v.X, v.Y, v.Z);

    /// <summary>A move at a point near <paramref name="target"/> (within 1.5 m in each axis), stopping short of it or going past, or one in any direction.</summary>
    private static V3 Towards(Random random, V3 target)
    {
        if (random.Next(4) == 0)
        {
            return new V3(Uniform(random, -4, 4), Uniform(random, -4, 4), Uniform(random, -4, 4));
        }

        var near = new V3(target.X + Uniform(random, -1.5, 1.5), target.Y + Uniform(random, -1.5, 1.5), target.Z + Uniform(random, -1.5, 1.5));
        return near * Uniform(random, 0.3, 2);
    }

    [Fact]
    public void Random_polygons_are_met_where_the_reference_meets_them()
    {
        var random = new Random(11);
        int met = 0, edgesOrCorners = 0;
        for (int i = 0; i < 800; i++)
        {
            // A convex polygon of 3 to 6 corners on an ellipse in a random plane, either winding.
            V3 n = Unit(new V3(Uniform(random, -1, 1), Uniform(random, -1, 1), Uniform(random, -1, 1)));
            V3 u = Unit(V3.Cross(n, Math.Abs(n.X) < 0.9 ? new V3(1, 0, 0) : new V3(0, 1, 0)));
            V3 w = V3.Cross(n, u);
            var centre = new V3(Uniform(random, -2, 2), Uniform(random, -2, 2), Uniform(random, -2, 2));
            double a = Uniform(random, 0.3, 1.5), b = Uniform(random, 0.3, 1.5);
            int count = random.Next(3, 7);
            double[] angles = [.. Enumerable.Range(0, count).Select(k => (k + Uniform(random, 0.1, 0.9)) * 2 * Math.PI / count)];
            var corners = angles.Select(t => centre + (u * (a * Math.Cos(t))) + (w * (b * Math.Sin(t)))).ToList();
            if (random.Next(2) == 0)
            {
                corners.Reverse();
            }

            var polygon = new Polygon(corners, SurfaceKind.CellWall, 5, "polygon");
            V3 move = Towards(random, centre);
            double r = RadiusOf(random);
            if (polygon.Distance(Origin) <= r + 1e-3)
            {
                continue;
            }

            var s = new SweptSphere(D(Origin), D(move), r);
            s.Polygon([.. corners.Select(D)], new ShapeName(SurfaceKind.CellWall, 5), SurfaceKind.CellCeiling);
            Hit? hit = new CastReference([polygon]).Cast(Origin, move, r);
            string what = FormattableString.Invariant($"case {i}: r {r}, move {move}, corners [{string.Join(", ", corners)}]");
            ShouldAgree(in s, hit, what);
            if (hit is not null)
            {
                met++;
                V3 foot = hit.Centre - (polygon.Normal * V3.Dot(hit.Centre - corners[0], polygon.Normal));
                if ((foot - hit.Point).Length > 1e-6)
                {
                    edgesOrCorners++;
                }

                bool facingDown = polygon.Normal.Z <= -PhysicsConstants.FloorZ;
                s.Kind.Should().Be(facingDown ? SurfaceKind.CellCeiling : SurfaceKind.CellWall, what);
                s.Id.Should().Be(5u);
            }
        }

        met.Should().BeGreaterThan(120, "enough contacts to be a test");
        edgesOrCorners.Should().BeGreaterThan(30, "edges and corners among them");
    }

    [Fact]
    public void Random_cylinders_are_met_where_the_reference_meets_them()
    {
        var random = new Random(12);
        int met = 0, sides = 0, caps = 0, rims = 0;
        for (int i = 0; i < 800; i++)
        {
            double x = Uniform(random, -2, 2), y = Uniform(random, -2, 2), radius = Uniform(random, 0.1, 1);
            double z0 = Uniform(random, -2.5, 1.5), z1 = z0 + Uniform(random, 0.2, 2);
            var cylinder = new Cylinder(x, y, radius, z0, z1, SurfaceKind.Cylinder, 6, "cylinder");
            V3 move = Towards(random, new V3(x, y, 0.5 * (z0 + z1)));
            double r = RadiusOf(random);
            if (cylinder.Distance(Origin) <= r + 1e-3)
            {
                continue;
            }

            var s = new SweptSphere(D(Origin), D(move), r);
            s.Cylinder(x, y, radius, z0, z1, new ShapeName(SurfaceKind.Cylinder, 6));
            Hit? hit = new CastReference([cylinder]).Cast(Origin, move, r);
            string what = FormattableString.Invariant($"case {i}: r {r}, move {move}, axis ({x}, {y}) radius {radius} z {z0}..{z1}");
            ShouldAgree(in s, hit, what);
            if (hit is not null)
            {
                met++;
                s.Kind.Should().Be(SurfaceKind.Cylinder);
                s.Id.Should().Be(6u);
                bool onSide = hit.Point.Z > z0 + 1e-9 && hit.Point.Z < z1 - 1e-9;
                double rho = Math.Sqrt(((hit.Point.X - x) * (hit.Point.X - x)) + ((hit.Point.Y - y) * (hit.Point.Y - y)));
                if (onSide)
                {
                    sides++;
                }
                else if (rho < radius - 1e-9)
                {
                    caps++;
                }
                else
                {
                    rims++;
                }
            }
        }

        met.Should().BeGreaterThan(150, "enough contacts to be a test");
        sides.Should().BeGreaterThan(20);
        caps.Should().BeGreaterThan(20);
        rims.Should().BeGreaterThan(10);
    }

    [Fact]
    public void Random_bilinear_cells_are_met_where_the_lowest_point_first_falls_through_the_patch()
    {
        var random = new Random(13);
        int met = 0, twisted = 0, checkedCases = 0;
        for (int i = 0; i < 1500; i++)
        {
            double x0 = Uniform(random, -3, 1), y0 = Uniform(random, -3, 1), size = Uniform(random, 1, 4);
            var h = new CornerHeights(Uniform(random, -3, 1), Uniform(random, -3, 1), Uniform(random, -3, 1), Uniform(random, -3, 1));
            var move = new D3(Uniform(random, -4, 4), Uniform(random, -4, 4), Uniform(random, -4, 4));
            double r = RadiusOf(random);
            if (BilinearReference(x0, y0, size, in h, move, r) is not (bool sure, double expected))
            {
                continue;
            }

            checkedCases++;
            var s = new SweptSphere(default, move, r);
            s.BilinearCell(x0, y0, size, in h, 0x51);
            string what = FormattableString.Invariant($"case {i}: r {r}, move {move}, cell ({x0}, {y0}) size {size}, {h}");
            if (!sure)
            {
                ShouldMiss(in s, what);
                continue;
            }

            s.Found.Should().BeTrue(what);
            s.T.Should().BeApproximately(expected, Fraction, what);
            s.Kind.Should().Be(SurfaceKind.Terrain);
            s.Id.Should().Be(0x51u);

            // The normal: up, across the patch's gradient there (central differences: exact for a bilinear patch).
            D3 c = move * s.T;
            double ux = (c.X - x0) / size, vy = (c.Y - y0) / size, e = 1e-4;
            double gx = (Height(in h, ux + e, vy) - Height(in h, ux - e, vy)) / (2 * e * size);
            double gy = (Height(in h, ux, vy + e) - Height(in h, ux, vy - e)) / (2 * e * size);
            double l = Math.Sqrt(1 + (gx * gx) + (gy * gy));
            s.Normal.X.Should().BeApproximately(-gx / l, Direction, what);
            s.Normal.Y.Should().BeApproximately(-gy / l, Direction, what);
            s.Normal.Z.Should().BeApproximately(1 / l, Direction, what);
            met++;
            if (Math.Abs(h.NE - h.NW - h.SE + h.SW) > 0.5)
            {
                twisted++;
            }
        }

        checkedCases.Should().BeGreaterThan(1000);
        met.Should().BeGreaterThan(150, "enough contacts to be a test");
        twisted.Should().BeGreaterThan(80);
    }

    [Fact]
    public void Roots_of_random_polynomials_are_their_roots_in_the_interval()
    {
        var random = new Random(14);
        Span<double> roots = stackalloc double[6];
        for (int i = 0; i < 3000; i++)
        {
            int degree = random.Next(1, 5);
            double[] chosen = [.. Enumerable.Range(0, degree).Select(_ => Uniform(random, -0.5, 1.5)).Order()];
            double lo = Uniform(random, -0.3, 0.5), hi = lo + Uniform(random, 0.2, 1.2), scale = Uniform(random, 0.1, 10) * (random.Next(2) == 0 ? 1 : -1);
            bool apart = true;
            for (int k = 0; k < degree; k++)
            {
                apart &= Math.Abs(chosen[k] - lo) > 1e-3 && Math.Abs(chosen[k] - hi) > 1e-3 && (k == 0 || chosen[k] - chosen[k - 1] > 0.05);
            }

            if (!apart)
            {
                continue;
            }

            double[] c = [.. Monic(chosen).Select(v => v * scale)];
            double[] inside = [.. chosen.Where(t => t >= lo && t <= hi)];
            string what = FormattableString.Invariant($"case {i}: roots [{string.Join(", ", chosen)}] × {scale} in {lo}..{hi}");
            int n = SweptSphere.Roots(c, lo, hi, roots);
            n.Should().Be(inside.Length, what);
            for (int k = 0; k < n; k++)
            {
                roots[k].Should().BeApproximately(inside[k], 1e-9, what);
            }
        }
    }

    private static void ShouldAgree(in SweptSphere s, Hit? hit, string what)
    {
        if (hit is null)
        {
            ShouldMiss(in s, what);
            return;
        }

        s.Found.Should().BeTrue($"{what}: the reference meets it, {hit}");
        s.T.Should().BeApproximately(hit.T, Fraction, $"{what}: {hit}");
        D3 normal = s.Normal;
        hit.Normals.Should().Contain(
            n => Math.Abs(n.X - normal.X) < Direction && Math.Abs(n.Y - normal.Y) < Direction && Math.Abs(n.Z - normal.Z) < Direction,
            $"{what}: normal {normal}, {hit}");
    }

    private static void ShouldMiss(in SweptSphere s, string what)
    {
        s.Found.Should().BeFalse($"{what}: met at {s.T} with {s.Normal}");
        s.T.Should().Be(double.PositiveInfinity, what);
    }

    private static V3 Unit(V3 v) => v * (1 / v.Length);

    private static double Height(in CornerHeights h, double u, double v) =>
        (h.SW * (1 - u) * (1 - v)) + (h.SE * u * (1 - v)) + (h.NW * (1 - u) * v) + (h.NE * u * v);

    /// <summary>
    /// Where the lowest point of the sphere (or the ray) first goes down through the patch while over the cell, by the
    /// definition: the gap g(t) = z(t) − r − h(x(t), y(t)) over the fractions in 0..1 whose centre is over the cell; met at
    /// the first of them when it starts below (g &lt; 0) going down, else at the first fall through 0. Null when the case
    /// is too near a tie for a sampled answer (a graze, a start on the patch, a fraction on the cell's edge).
    /// </summary>
    private static (bool Met, double T)? BilinearReference(double x0, double y0, double size, in CornerHeights h, D3 move, double r)
    {
        // The fractions over the cell: clip 0..1 to the square, in double, away from its edges.
        double tIn = 0, tOut = 1;
        foreach ((double p0, double dp) in new[] { (-x0 / size, move.X / size), (-y0 / size, move.Y / size) })
        {
            if (dp == 0)
            {
                if (p0 < 0 || p0 > 1)
                {
                    return (false, 0);
                }

                continue;
            }

            double ta = -p0 / dp, tb = (1 - p0) / dp;
            tIn = Math.Max(tIn, Math.Min(ta, tb));
            tOut = Math.Min(tOut, Math.Max(ta, tb));
        }

        if (tIn > tOut + 1e-9)
        {
            return (false, 0);
        }

        if (tOut - tIn < 1e-6)
        {
            return null;
        }

        CornerHeights heights = h;
        double Gap(double t) => (move.Z * t) - r - Height(in heights, ((move.X * t) - x0) / size, ((move.Y * t) - y0) / size);

        const int Steps = 4000;
        double g0 = Gap(tIn);
        if (Math.Abs(g0) < 1e-6)
        {
            return null;
        }

        if (g0 < 0)
        {
            double slope = Gap(tIn + 1e-7) - g0;
            return Math.Abs(slope) < 1e-12 ? null : slope < 0 ? (true, tIn) : (false, 0);
        }

        double previous = tIn, gPrevious = g0;
        for (int k = 1; k <= Steps; k++)
        {
            double t = tIn + ((tOut - tIn) * k / Steps), g = Gap(t);
            if (g < 0)
            {
                double lo = previous, hi = t;
                for (int j = 0; j < 200 && hi - lo > 1e-15; j++)
                {
                    double mid = 0.5 * (lo + hi);
                    (lo, hi) = Gap(mid) < 0 ? (lo, mid) : (mid, hi);
                }

                double falling = Gap(lo + 1e-6) - Gap(lo - 1e-6);
                return falling > -1e-9 || hi > 1 - 1e-9 ? null : (true, hi);
            }

            if (g < 1e-5 && g <= gPrevious)
            {
                // Near a graze (a double root close by): too near a tie to call.
                double next = Gap(Math.Min(t + ((tOut - tIn) / Steps), tOut));
                if (next >= g)
                {
                    return null;
                }
            }

            (previous, gPrevious) = (t, g);
        }

        return Math.Abs(Gap(tOut)) < 1e-6 ? null : (false, 0);
    }

    /// <summary>The coefficients (constant first) of the monic polynomial with these roots.</summary>
    private static double[] Monic(double[] roots)
    {
        double[] c = [1];
        foreach (double root in roots)
        {
            var next = new double[c.Length + 1];
            for (int i = 0; i < c.Length; i++)
            {
                next[i + 1] += c[i];
                next[i] -= root * c[i];
            }

            c = next;
        }

        return c;
    }
}
