using AcDream.Core.Physics.Surfaces;
namespace AcDream.Core.Physics.Casting;

// SweptSphere against a cylinder: its side, its caps and (for a sphere) its rims, the rims' quartic solved by its roots.
internal partial struct SweptSphere
{
    /// <summary>
    /// An upright cylinder (axis <paramref name="axisX"/>, <paramref name="axisY"/> relative to the start; radius
    /// <paramref name="radius"/>; from <paramref name="z0"/> to <paramref name="z1"/> relative to the start), as
    /// <paramref name="name"/>.
    /// </summary>
    public void Cylinder(double axisX, double axisY, double radius, double z0, double z1, ShapeName name)
    {
        double dx = Move.X, dy = Move.Y, dz = Move.Z;
        double a = (dx * dx) + (dy * dy);

        // The side: the centre's horizontal distance from the axis reaches radius + R while its Z is in z0..z1.
        double reach = radius + Radius;
        double b = -((dx * axisX) + (dy * axisY));
        double c = (axisX * axisX) + (axisY * axisY) - (reach * reach);
        if (b < 0)
        {
            double t = /* Stryker disable once Unary : b < 0 needs a horizontal move, so a > 0 and t is always replaced */ -1;
            if (c < 0)
            {
                t = 0; // within reach of the axis already, moving towards it
            }
            else if (a > 0)
            {
                double disc = (b * b) - (a * c);
                t = disc >= 0 ? (-b - Math.Sqrt(disc)) / a : -1;
            }

            double z = dz * t;
            if (t >= 0 && MayKeep(t) && z >= z0 && z <= z1)
            {
                D3 centre = Move * t;
                Keep(t, Towards(new D3(centre.X - axisX, centre.Y - axisY, 0)), name);
            }
        }

        // The caps: the centre a radius above the top (or below the bottom) within the cylinder's radius, approached from
        // above it (below it); a centre already within the radius of the cap is met at once.
        if (dz < 0 && z1 < 0)
        {
            Cap(axisX, axisY, radius, z1 + Radius, 1.0, name);
        }

        if (dz > 0 && z0 > 0)
        {
            Cap(axisX, axisY, radius, z0 - Radius, -1.0, name);
        }

        if (Radius > 0)
        {
            Rim(axisX, axisY, radius, z1, 1.0, name);
            Rim(axisX, axisY, radius, z0, -1.0, name);
        }
    }

    /// <summary>
    /// The top cap (<paramref name="up"/> 1) or the bottom one (−1), which the caller has found the centre approaching:
    /// met where the centre reaches <paramref name="planeZ"/> (a radius beyond the cap) within <paramref name="radius"/>
    /// of the axis, at 0 when it starts within the radius of the cap's plane.
    /// </summary>
    private void Cap(double axisX, double axisY, double radius, double planeZ, double up, ShapeName name)
    {
        double t = Math.Max(planeZ / Move.Z, 0.0);
        if (!MayKeep(t))
        {
            // Stryker disable once Statement : Keep tests the same bounds again
            return;
        }

        double hx = (Move.X * t) - axisX, hy = (Move.Y * t) - axisY;
        if ((hx * hx) + (hy * hy) <= radius * radius)
        {
            Keep(t, new D3(0, 0, up), name);
        }
    }

    /// <summary>
    /// The rim circle at <paramref name="z"/> (the top's, <paramref name="up"/> 1, or the bottom's, −1): where the sphere
    /// first comes within its radius of the circle while beyond the cap and outside the side (the side and caps answer
    /// elsewhere). The centre is then on the torus about the circle: with ρ its distance from the axis and w its height
    /// over the circle, (ρ − rc)² + w² = R², that is S = 2·rc·ρ with S = ρ² + w² + rc² − R², whose square
    /// P = S² − 4·rc²·ρ² is a quartic in the fraction. Its roots are isolated exactly (<see cref="Roots"/>), so a sphere
    /// that dips into the rim by any depth is met, at the first root where S ≥ 0.
    /// </summary>
    private void Rim(double axisX, double axisY, double radius, double z, double up, ShapeName name)
    {
        double limit = Math.Min(T, 1.0);
        double reach = radius + Radius;
        // Stryker disable once Logical,Statement : a pre-check: the torus's roots are found in any case
        if (Apart(Move.Z, limit, z, Radius) || Apart(Move.X, limit, axisX, reach) || Apart(Move.Y, limit, axisY, reach))
        {
            return; // the path's box misses the torus's
        }

        // ρ² = a2·t² + a1·t + a0; S = s2·t² + s1·t + s0.
        double a2 = (Move.X * Move.X) + (Move.Y * Move.Y), a1 = -2 * ((Move.X * axisX) + (Move.Y * axisY)), a0 = (axisX * axisX) + (axisY * axisY);
        double s2 = a2 + (Move.Z * Move.Z), s1 = a1 - (2 * Move.Z * z), s0 = a0 + (z * z) + (radius * radius) - (Radius * Radius);
        double k = 4 * radius * radius;
        Span<double> p = [(s0 * s0) - (k * a0), (2 * s1 * s0) - (k * a1), (s1 * s1) + (2 * s2 * s0) - (k * a2), 2 * s2 * s1, s2 * s2];
        // Within the torus at the start: met at once when moving towards the circle, else free of it.
        double w0 = -z, rho0 = Math.Sqrt(a0);
        if ((((rho0 - radius) * (rho0 - radius)) + (w0 * w0)) <= Radius * Radius)
        {
            if (/* Stryker disable once Arithmetic : up is ±1 */ w0 * up > 0 && rho0 > radius)
            {
                double f0 = radius / rho0; // (ρ above the circle's radius: not 0)
                var away0 = new D3(-axisX + (axisX * f0), -axisY + (axisY * f0), w0);
                if (D3.Dot(away0, Move) < 0)
                {
                    Keep(0, Towards(away0), name);
                }
            }

            return;
        }

        Span<double> roots = stackalloc double[6];
        int count = Roots(p, 0, limit, roots);
        for (int i = 0; i < count; i++)
        {
            double t = roots[i];
            if ((s2 * t * t) + (s1 * t) + s0 < 0)
            {
                continue; // a root of the square only
            }

            D3 centre = Move * t;
            double hx = centre.X - axisX, hy = centre.Y - axisY, rho = Math.Sqrt((hx * hx) + (hy * hy));
            if ((centre.Z - z) * up > 0 && rho > radius)
            {
                double f = radius / rho; // (ρ above the circle's radius: not 0)
                Keep(t, Towards(new D3(hx - (hx * f), hy - (hy * f), centre.Z - z)), name);
            }

            return; // the first crossing of the torus: beyond it the side or a cap answers
        }
    }

    /// <summary>
    /// Whether the path's stretch along one axis, from 0 to <paramref name="move"/> · <paramref name="limit"/>, stays
    /// farther than <paramref name="half"/> from <paramref name="centre"/> (touching at the bound is not apart): one axis
    /// of a box pre-check.
    /// </summary>
    internal static bool Apart(double move, double limit, double centre, double half)
    {
        double end = move * limit;
        return Math.Min(0, end) > centre + half || Math.Max(0, end) < centre - half;
    }

    /// <summary>
    /// The real roots in lo..hi of the polynomial with coefficients <paramref name="c"/> (constant first, degree at most
    /// 4), ascending, into <paramref name="roots"/>; returns how many. The roots of its derivative (found the same way,
    /// down to a line) split lo..hi into stretches where it is monotonic, and each sign change is bisected to the last
    /// bit: exact, deterministic, and safe at double and near-double roots.
    /// </summary>
    internal static int Roots(ReadOnlySpan<double> c, double lo, double hi, Span<double> roots)
    {
        int n = c.Length - 1, count = 0;
        if (n == 1)
        {
            if (c[1] != 0)
            {
                double r = -c[0] / c[1];
                if (r >= lo && r <= hi)
                {
                    roots[count++] = r;
                }
            }

            return count;
        }

        Span<double> d = stackalloc double[n];
        for (int i = 0; i < n; i++)
        {
            d[i] = (i + 1) * c[i + 1];
        }

        Span<double> turns = stackalloc double[n + 1]; // the derivative's n − 1 roots, and room for a doubled one
        int m = Roots(d, lo, hi, turns);
        double a = lo, fa = Eval(c, lo);
        for (int j = 0; j <= m; j++)
        {
            double b = j < m ? turns[j] : hi, fb = Eval(c, b);
            if (count == roots.Length)
            {
                break; // (a degree-n polynomial has n roots; flat stretches of rounding could list one twice)
            }

            if (fa == 0)
            {
                if (count == 0 || roots[count - 1] != a)
                {
                    roots[count++] = a;
                }
            }
            else if (fb != 0 && (fa < 0) != (fb < 0))
            {
                roots[count++] = Bisect(c, a, b, fa);
            }

            (a, fa) = (b, fb);
        }

        if (fa == 0 && count < roots.Length && (count == 0 || roots[count - 1] != a))
        {
            roots[count++] = a;
        }

        return count;
    }

    private static double Bisect(ReadOnlySpan<double> c, double a, double b, double fa)
    {
        for (int i = 0; i < 200; i++)
        {
            double mid = a + ((b - a) * 0.5);
            if (/* Stryker disable once Logical : going on at one step changes neither end (the ends' values are not 0) until the bound */ mid <= a || mid >= b)
            {
                // Stryker disable once Statement : going on at one step changes neither end (the ends' values are not 0) until the bound
                break; // the interval is one representable step
            }

            double fm = Eval(c, mid);
            if (fm == 0)
            {
                return mid;
            }

            if ((fm < 0) == (fa < 0))
            {
                (a, fa) = (mid, fm);
            }
            else
            {
                b = mid;
            }
        }

        return a;
    }

    private static double Eval(ReadOnlySpan<double> c, double t)
    {
        double v = 0;
        for (int i = c.Length - 1; i >= 0; i--)
        {
            v = (v * t) + c[i];
        }

        return v;
    }
}
