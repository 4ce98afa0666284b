using System.Numerics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics;

/// <summary>
/// A sphere swept along a segment, and the earliest contact found so far: every shape a cast meets is tested here, in
/// double precision, relative to the segment's start (so the arithmetic keeps its precision wherever the frame is).
/// Coordinates are those of the cast's frame: the landblock-local frame of its start; a shape of another landblock is
/// passed with that landblock's offset. Polygons and triangles are two-sided: met from either side.
/// </summary>
/// <remarks>
/// A contact is the first fraction t in 0..1 at which the sphere touches the shape's closed set: the face (a plane
/// crossing at the radius, its touch point inside), an edge (a capsule's side) or a corner (a sphere), each in closed
/// form; a cylinder's side, caps and (for a sphere) its rims. A sphere that starts overlapping a shape and moves
/// towards it is stopped at 0; moving away or along, it is free of it. A contact at the same fraction as the one kept
/// does not replace it, so the first shape tested of those met at once is named.
/// </remarks>
internal struct SweptSphere
{
    public SweptSphere(D3 start, D3 move, double radius)
    {
        (Start, Move, Radius, T) = (start, move, radius, double.PositiveInfinity);
        MoveSquared = D3.Dot(move, move);
        (_from, _to) = (0.0, 1.0);
    }

    /// <summary>The fractions within which a contact is kept (<see cref="Within"/>); 0..1 otherwise.</summary>
    private double _from, _to;

    public D3 Start { get; }

    public D3 Move { get; }

    public double Radius { get; }

    public double MoveSquared { get; }

    /// <summary>The earliest contact's fraction; +∞ for none.</summary>
    public double T { get; private set; }

    /// <summary>The earliest contact's unit normal, pointing at the sphere.</summary>
    public D3 Normal { get; private set; }

    public SurfaceKind Kind { get; private set; }

    public uint Id { get; private set; }

    /// <summary>Whether a contact has been found.</summary>
    public readonly bool Found => T <= 1.0;

    /// <summary>The centre at fraction t, in the cast's frame.</summary>
    public readonly D3 At(double t) => Start + (Move * t);

    /// <summary>Keeps only contacts from fraction <paramref name="from"/> to <paramref name="to"/> until <see cref="Everywhere"/>: shapes tested only for a stretch of the path.</summary>
    public void Within(double from, double to) => (_from, _to) = (from, Math.Min(to, 1.0));

    /// <summary>Keeps contacts anywhere along the path again.</summary>
    public void Everywhere() => (_from, _to) = (0.0, 1.0);

    /// <summary>Forgets every contact found (a centre passing in through a doorway: what lay beyond it outdoors is behind the cell's own walls).</summary>
    public void Forget() => (T, Kind, Id) = (double.PositiveInfinity, SurfaceKind.None, 0);

    /// <summary>Ends the cast at <paramref name="t"/> when nothing was met before it (a portal to a cell not loaded, land not loaded).</summary>
    public void Stop(double t, D3 normal, SurfaceKind kind, uint id) => Keep(t, normal, kind, id);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private void Keep(double t, D3 normal, SurfaceKind kind, uint id)
    {
        if (t < T && t <= _to && t >= _from)
        {
            (T, Normal, Kind, Id) = (Math.Max(t, 0.0), normal, kind, id);
        }
    }

    /// <summary>
    /// The polygon (vertices relative to <see cref="Start"/>, convex, in winding order), as <paramref name="kind"/>
    /// <paramref name="id"/>; <paramref name="kindFacingDown"/> names it when its normal points down (a ceiling).
    /// </summary>
    public void Polygon(ReadOnlySpan<D3> v, SurfaceKind kind, uint id, SurfaceKind kindFacingDown)
    {
        // Newell normal, through the vertices' mean.
        (D3 newell, D3 sum) = D3.Newell(v);
        (double nx, double ny, double nz, double cx, double cy, double cz) = (newell.X, newell.Y, newell.Z, sum.X, sum.Y, sum.Z);
        double length = Math.Sqrt((nx * nx) + (ny * ny) + (nz * nz));
        if (!(length > 1e-12))
        {
            return; // no area
        }

        var n = new D3(nx / length, ny / length, nz / length);
        SurfaceKind named = n.Z <= -PhysicsConstants.FloorZ ? kindFacingDown : kind;
        var c = new D3(cx / v.Length, cy / v.Length, cz / v.Length);
        double s0 = -D3.Dot(n, c); // the start's signed distance from the plane
        double rate = D3.Dot(n, Move);
        if (Radius > 0 && Math.Abs(s0) < Radius && Overlapping(v, n, s0, rate, named, id))
        {
            return; // the sphere starts within its radius of the polygon: met at once, or free of it
        }

        double side = s0 > 0 || (s0 == 0 && rate > 0) ? 1.0 : -1.0; // a start on the plane is on the side it moves to: away
        if (side * rate < 0)
        {
            // Approaching the plane: the face is met when the centre is a radius from it.
            double t = Math.Max((Math.Abs(s0) - Radius) / (-side * rate), 0.0); // (0 only when the start's foot is off the polygon)
            if (t < T && t <= 1.0)
            {
                D3 touch = (Move * t) - (n * (side * Radius)); // (only its place in the plane matters to the inside test)
                if (Inside(v, n, touch))
                {
                    Keep(t, n * side, named, id);
                    return; // the face is the first of this polygon met
                }
            }
        }

        if (Radius > 0)
        {
            for (int i = 0, j = v.Length - 1; i < v.Length; j = i++)
            {
                Edge(v[j], v[i], named, id);
                Corner(v[i], named, id);
            }
        }
    }

    /// <summary>
    /// Whether the sphere starts within its radius of the polygon (the start <paramref name="s0"/> from its plane, less
    /// than the radius), which then decides for the whole polygon: the sphere is met at once when it moves into the
    /// polygon's plane from its side (<paramref name="rate"/> the move's speed along the normal), and is free of it moving
    /// along the plane or away. Decided by the plane, not by the nearest point: a sphere gliding over a floor of many
    /// triangles comes nearer to the edges it crosses, but not into the floor.
    /// </summary>
    private bool Overlapping(ReadOnlySpan<D3> v, D3 n, double s0, double rate, SurfaceKind kind, uint id)
    {
        D3 nearest = n * -s0; // the start's foot on the plane
        if (!Inside(v, n, nearest))
        {
            double best = double.PositiveInfinity;
            for (int i = 0, j = v.Length - 1; i < v.Length; j = i++)
            {
                D3 e = v[i] - v[j];
                double ee = D3.Dot(e, e), s = ee > 0 ? Math.Clamp(D3.Dot(-v[j], e) / ee, 0.0, 1.0) : 0.0;
                D3 q = v[j] + (e * s);
                double d = D3.Dot(q, q);
                if (d < best)
                {
                    (best, nearest) = (d, q);
                }
            }
        }

        if (!(D3.Dot(nearest, nearest) < Radius * Radius))
        {
            return false; // not within the radius: the sweep below finds the contact
        }

        double side = s0 > 0 ? 1.0 : -1.0;
        if (s0 != 0 && side * rate < 0)
        {
            Keep(0, n * side, kind, id);
        }

        return true;
    }

    /// <summary>Whether <paramref name="p"/>, on the plane of the convex polygon <paramref name="v"/> (normal <paramref name="n"/>), is inside it or within <see cref="PhysicsConstants.CastEdgeTolerance"/> of its edges.</summary>
    private static bool Inside(ReadOnlySpan<D3> v, D3 n, D3 p)
    {
        for (int i = 0, j = v.Length - 1; i < v.Length; j = i++)
        {
            D3 e = v[i] - v[j];
            D3 inward = D3.Cross(n, e);
            double el = e.Length;
            if (el > 0 && D3.Dot(p - v[j], inward) < -PhysicsConstants.CastEdgeTolerance * el)
            {
                return false;
            }
        }

        return true;
    }

    /// <summary>The segment a–b (relative to the start) as a capsule of the sphere's radius.</summary>
    private void Edge(D3 a, D3 b, SurfaceKind kind, uint id)
    {
        D3 e = b - a, m = -a;
        double ee = D3.Dot(e, e), ed = D3.Dot(e, Move), em = D3.Dot(e, m);
        if (!(ee > 0))
        {
            return;
        }

        double A = (ee * MoveSquared) - (ed * ed);
        double B = (ee * D3.Dot(m, Move)) - (ed * em);
        double C = (ee * (D3.Dot(m, m) - (Radius * Radius))) - (em * em);
        if (C < 0 || !(A > 1e-12 * ee * MoveSquared) || !(B < 0))
        {
            // Within the radius of the edge's line already (beside the segment its ends answer; on it, the polygon's start
            // rule has decided), moving along the edge (its ends answer), or away.
            return;
        }

        double disc = (B * B) - (A * C);
        if (disc < 0)
        {
            return;
        }

        double t = (-B - Math.Sqrt(disc)) / A;
        if (!(t < T) || t > 1.0)
        {
            return;
        }

        D3 centre = Move * t;
        double s = (em + (t * ed)) / ee;
        if (s < 0 || s > 1)
        {
            return;
        }

        Keep(t, Towards(centre - (a + (e * s))), kind, id);
    }

    /// <summary>The point <paramref name="p"/> (relative to the start) as a sphere of the cast's radius.</summary>
    private void Corner(D3 p, SurfaceKind kind, uint id)
    {
        D3 m = -p;
        double b = D3.Dot(m, Move), c = D3.Dot(m, m) - (Radius * Radius);
        if (!(b < 0) || c < 0)
        {
            return; // moving away or along; or within the radius already, where the polygon's start rule has decided
        }

        double disc = (b * b) - (MoveSquared * c);
        if (disc < 0)
        {
            return;
        }

        double t = (-b - Math.Sqrt(disc)) / MoveSquared;
        if (t < T && t <= 1.0)
        {
            Keep(t, Towards((Move * t) - p), kind, id);
        }
    }

    /// <summary>
    /// An upright cylinder (axis <paramref name="axisX"/>, <paramref name="axisY"/> relative to the start; radius
    /// <paramref name="radius"/>; from <paramref name="z0"/> to <paramref name="z1"/> relative to the start).
    /// </summary>
    public void Cylinder(double axisX, double axisY, double radius, double z0, double z1, SurfaceKind kind, uint id)
    {
        double dx = Move.X, dy = Move.Y, dz = Move.Z;
        double a = (dx * dx) + (dy * dy);

        // The side: the centre's horizontal distance from the axis reaches radius + R while its Z is in z0..z1.
        double reach = radius + Radius;
        double b = -((dx * axisX) + (dy * axisY));
        double c = (axisX * axisX) + (axisY * axisY) - (reach * reach);
        if (b < 0)
        {
            double t = -1;
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
            if (t >= 0 && t < T && t <= 1.0 && z >= z0 && z <= z1)
            {
                D3 centre = Move * t;
                Keep(t, Towards(new D3(centre.X - axisX, centre.Y - axisY, 0)), kind, id);
            }
        }

        // The caps: the centre a radius above the top (or below the bottom) within the cylinder's radius, approached from
        // above it (below it); a centre already within the radius of the cap is met at once.
        Cap(axisX, axisY, radius, z1 + Radius, dz < 0 && z1 < 0, 1.0, kind, id);
        Cap(axisX, axisY, radius, z0 - Radius, dz > 0 && z0 > 0, -1.0, kind, id);

        if (Radius > 0)
        {
            Rim(axisX, axisY, radius, z1, 1.0, kind, id);
            Rim(axisX, axisY, radius, z0, -1.0, kind, id);
        }
    }

    private void Cap(double axisX, double axisY, double radius, double planeZ, bool approaching, double up, SurfaceKind kind, uint id)
    {
        if (!approaching)
        {
            return;
        }

        double t = Math.Max(planeZ / Move.Z, 0.0);
        if (!(t < T) || t > 1.0)
        {
            return;
        }

        double hx = (Move.X * t) - axisX, hy = (Move.Y * t) - axisY;
        if ((hx * hx) + (hy * hy) <= radius * radius)
        {
            Keep(t, new D3(0, 0, up), kind, id);
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
    private void Rim(double axisX, double axisY, double radius, double z, double up, SurfaceKind kind, uint id)
    {
        double limit = Math.Min(T, 1.0);
        double reach = radius + Radius;
        if (Math.Min(0, Move.Z * limit) > z + Radius || Math.Max(0, Move.Z * limit) < z - Radius
            || Math.Min(0, Move.X * limit) > axisX + reach || Math.Max(0, Move.X * limit) < axisX - reach
            || Math.Min(0, Move.Y * limit) > axisY + reach || Math.Max(0, Move.Y * limit) < axisY - reach)
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
            double f0 = rho0 > 0 ? radius / rho0 : 0;
            var away0 = new D3(-axisX + (axisX * f0), -axisY + (axisY * f0), w0);
            if (w0 * up > 0 && rho0 > radius && D3.Dot(away0, Move) < 0)
            {
                Keep(0, Towards(away0), kind, id);
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
            double f = rho > 0 ? radius / rho : 0;
            var away = new D3(hx - (hx * f), hy - (hy * f), centre.Z - z);
            if ((centre.Z - z) * up > 0 && rho > radius)
            {
                Keep(t, Towards(away), kind, id);
            }

            return; // the first crossing of the torus: beyond it the side or a cap answers
        }
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
            if (mid <= a || mid >= b)
            {
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

    /// <summary>
    /// The ray (radius 0) or the lowest point (radius R) of the sphere against the bilinear patch of one terrain cell
    /// (south-west corner at x0, y0 relative to the start, side <c>size</c> metres; corner heights relative to the
    /// start), met from above, as terrain cell <c>id</c>.
    /// </summary>
    public void BilinearCell(double x0, double y0, double size, double hSW, double hSE, double hNW, double hNE, uint id)
    {
        // Along the ray: u = (tDx − x0)/size, v = (tDy − y0)/size; the lowest point's Z − h(u, v) is a quadratic in t.
        double u0 = -x0 / size, du = Move.X / size, v0 = -y0 / size, dv = Move.Y / size;
        double a = hSW, b = hSE - hSW, c = hNW - hSW, d = hNE - hNW - hSE + hSW; // h = a + b·u + c·v + d·u·v
        double k0 = -Radius - (a + (b * u0) + (c * v0) + (d * u0 * v0));
        double k1 = Move.Z - ((b * du) + (c * dv) + (d * ((u0 * dv) + (v0 * du))));
        double k2 = -(d * du * dv);

        // Earliest t in the cell's span of the ray where k0 + k1 t + k2 t² falls to 0 from above; below the patch where the
        // ray enters the cell, met at once moving down into it, free of it moving up.
        (double tIn, double tOut) = Span(u0, du, v0, dv);
        if (!(tIn <= tOut))
        {
            return;
        }

        double gapIn = k0 + (k1 * tIn) + (k2 * tIn * tIn), slopeIn = k1 + (2 * k2 * tIn);
        if (gapIn < 0 || (gapIn == 0 && slopeIn < 0))
        {
            if (slopeIn < 0 && tIn < T && tIn <= 1.0)
            {
                Keep(tIn, PatchNormal(u0 + (du * tIn), v0 + (dv * tIn), b, c, d, size), SurfaceKind.Terrain, id);
            }

            return;
        }

        double best = double.PositiveInfinity;
        if (Math.Abs(k2) < 1e-15)
        {
            if (k1 < 0)
            {
                best = -k0 / k1;
            }
        }
        else
        {
            double disc = (k1 * k1) - (4 * k2 * k0);
            if (disc >= 0)
            {
                double sq = Math.Sqrt(disc);
                double q = -0.5 * (k1 + (k1 >= 0 ? sq : -sq));
                double r1 = q / k2, r2 = q != 0 ? k0 / q : double.PositiveInfinity;
                foreach (double r in (ReadOnlySpan<double>)[r1, r2])
                {
                    if (r >= tIn && r < best && k1 + (2 * k2 * r) < 0)
                    {
                        best = r; // falling through the patch there (a root where the ray rises off it is not a contact)
                    }
                }
            }
        }

        if (best < tIn || best > tOut || !(best < T) || best > 1.0)
        {
            return;
        }

        Keep(best, PatchNormal(u0 + (du * best), v0 + (dv * best), b, c, d, size), SurfaceKind.Terrain, id);
    }

    /// <summary>The bilinear patch's unit normal (up) at (u, v), for h = a + b·u + c·v + d·u·v over a cell of side <paramref name="size"/>.</summary>
    private static D3 PatchNormal(double u, double v, double b, double c, double d, double size)
    {
        double gx = (b + (d * v)) / size, gy = (c + (d * u)) / size;
        double n = 1.0 / Math.Sqrt(1.0 + (gx * gx) + (gy * gy));
        return new D3(-gx * n, -gy * n, n);
    }

    /// <summary>The fractions of the ray within the unit square u, v ∈ 0..1 (empty: in &gt; out).</summary>
    private static (double In, double Out) Span(double u0, double du, double v0, double dv)
    {
        double tIn = 0, tOut = 1;
        Clip(u0, du, ref tIn, ref tOut);
        Clip(v0, dv, ref tIn, ref tOut);
        return (tIn, tOut);

        static void Clip(double s0, double ds, ref double tIn, ref double tOut)
        {
            if (ds == 0)
            {
                if (s0 < 0 || s0 > 1)
                {
                    (tIn, tOut) = (1, 0);
                }

                return;
            }

            double ta = -s0 / ds, tb = (1 - s0) / ds;
            (tIn, tOut) = (Math.Max(tIn, Math.Min(ta, tb)), Math.Min(tOut, Math.Max(ta, tb)));
        }
    }

    /// <summary>A contact's normal from the nearest point of the shape to the centre; against the move when they coincide.</summary>
    private readonly D3 Towards(D3 fromShape)
    {
        double l = fromShape.Length;
        return l > 0 ? fromShape * (1.0 / l) : -Move * (1.0 / Math.Sqrt(MoveSquared));
    }
}
