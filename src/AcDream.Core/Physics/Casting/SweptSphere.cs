using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Surfaces;

namespace AcDream.Core.Physics.Casting;

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
internal partial struct SweptSphere
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

    /// <summary>Ends the cast at <paramref name="t"/> when nothing was met before it (a portal to a cell not loaded, land not loaded), naming <paramref name="name"/>.</summary>
    public void Stop(double t, D3 normal, ShapeName name) => Keep(t, normal, name);

    /// <summary>
    /// Whether a contact at <paramref name="t"/> could be kept: before the one kept and not past the end. A pre-check
    /// that spares working out a normal <see cref="Keep"/> would refuse; <see cref="Keep"/> tests it again with the stretch.
    /// </summary>
    private readonly bool MayKeep(double t) => /* Stryker disable once Logical : a pre-check that Keep repeats */ t < T && t <= 1.0;

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private void Keep(double t, D3 normal, ShapeName name)
    {
        if (t < T && t <= _to && t >= _from)
        {
            (T, Normal, Kind, Id) = (Math.Max(t, 0.0), normal, name.Kind, name.Id);
        }
    }

    /// <summary>
    /// The polygon (vertices relative to <see cref="Start"/>, convex, in winding order), as <paramref name="name"/>;
    /// <paramref name="kindFacingDown"/> is its kind when its normal points down (a ceiling), with the same id.
    /// </summary>
    public void Polygon(ReadOnlySpan<D3> v, ShapeName name, SurfaceKind kindFacingDown)
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
        ShapeName named = n.Z <= -PhysicsConstants.FloorZ ? new ShapeName(kindFacingDown, name.Id) : name;
        var c = new D3(cx / v.Length, cy / v.Length, cz / v.Length);
        double s0 = -D3.Dot(n, c); // the start's signed distance from the plane
        double rate = D3.Dot(n, Move);
        if (Math.Abs(s0) < Radius && Overlapping(v, n, s0, rate, named))
        {
            return; // the sphere starts within its radius of the polygon: met at once, or free of it
        }

        double side = s0 > 0 || (s0 == 0 && rate > 0) ? 1.0 : -1.0; // a start on the plane is on the side it moves to: away
        if (/* Stryker disable once Arithmetic : side is ±1, so side / rate has the sign of side · rate (rate 0: ±∞ or NaN, whose t is never kept) */ side * rate < 0)
        {
            // Approaching the plane: the face is met when the centre is a radius from it.
            double t = Math.Max((Math.Abs(s0) - Radius) / (-side * rate), 0.0); // (0 only when the start's foot is off the polygon)
            if (MayKeep(t))
            {
                D3 touch = (Move * t) - (n * (side * Radius)); // (only its place in the plane matters to the inside test)
                if (Inside(v, n, touch))
                {
                    Keep(t, n * side, named);
                    // Stryker disable once Statement : its edges and corners come no earlier, and a tie is not kept
                    return; // the face is the first of this polygon met
                }
            }
        }

        if (Radius > 0)
        {
            for (int i = 0, j = v.Length - 1; i < v.Length; j = i++)
            {
                Edge(v[j], v[i], named);
                Corner(v[i], named);
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
    private bool Overlapping(ReadOnlySpan<D3> v, D3 n, double s0, double rate, ShapeName name)
    {
        D3 nearest = n * -s0; // the start's foot on the plane
        if (!Inside(v, n, nearest))
        {
            double best = double.PositiveInfinity;
            for (int i = 0, j = v.Length - 1; i < v.Length; j = i++)
            {
                D3 e = v[i] - v[j];
                double s = Math.Clamp(D3.Dot(-v[j], e) / Math.Max(D3.Dot(e, e), double.Epsilon), 0.0, 1.0); // (an edge of no length: 0)
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
            Keep(0, n * side, name);
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
    private void Edge(D3 a, D3 b, ShapeName name)
    {
        D3 e = b - a, m = -a;
        double ee = D3.Dot(e, e), ed = D3.Dot(e, Move), em = D3.Dot(e, m); // (an edge of no length has A 0: it returns below)
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
            // Stryker disable once Statement : the root of a negative discriminant is NaN, which is not kept
            return;
        }

        double t = (-B - Math.Sqrt(disc)) / A;
        if (!MayKeep(t))
        {
            // Stryker disable once Statement : Keep tests the same bounds again
            return;
        }

        D3 centre = Move * t;
        double s = (em + (t * ed)) / ee;
        if (s < 0 || s > 1)
        {
            return;
        }

        Keep(t, Towards(centre - (a + (e * s))), name);
    }

    /// <summary>The point <paramref name="p"/> (relative to the start) as a sphere of the cast's radius.</summary>
    private void Corner(D3 p, ShapeName name)
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
            // Stryker disable once Statement : the root of a negative discriminant is NaN, which is not kept
            return;
        }

        double t = (-b - Math.Sqrt(disc)) / MoveSquared;
        if (MayKeep(t))
        {
            Keep(t, Towards((Move * t) - p), name);
        }
    }

    /// <summary>A contact's normal from the nearest point of the shape to the centre; against the move when they coincide.</summary>
    private readonly D3 Towards(D3 fromShape)
    {
        double l = fromShape.Length;
        return l > 0 ? fromShape * (1.0 / l) : -Move * (1.0 / Math.Sqrt(MoveSquared));
    }
}

/// <summary>
/// What a contact with a shape names: the kind of surface and its id (a cell's, an object's, a mover's, a terrain
/// cell's). Eight bytes, passed by value.
/// </summary>
internal readonly record struct ShapeName(SurfaceKind Kind, uint Id);
