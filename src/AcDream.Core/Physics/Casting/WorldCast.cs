using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Casting;

/// <summary>
/// A cast through the world (<see cref="PhysicsEngine.Cast"/>): the sphere's centre followed piece by piece, in a cell
/// or outdoors, and in each piece every shape the sphere can reach there tested (<see cref="SweptSphere"/>), in the
/// landblock-local frame of the start.
/// </summary>
/// <remarks>
/// <para>
/// In a cell: the shapes of the cell, of every cell reached from it through portals whose bounds meet the rest of the
/// path (grown by the radius), of the objects standing in them and of those standing in other cells that reach into
/// them (<see cref="LandblockEntry.Reaching"/>); near a portal to the outdoors, also the outdoor
/// objects and the walls of the building's cells within the radius of that portal (a shell's door frame); the movers
/// near. The centre leaves the cell through the first portal its segment passes out through: on into the neighbour,
/// or outdoors; a portal to a cell that is not loaded stops it as a wall.
/// </para>
/// <para>
/// Outdoors: the centre's path is walked 24 m terrain cell by cell (across seams: the cell's landblock, in the
/// start's frame); in each the terrain, outdoor objects, the walls of buildings' cells met from outdoors and the
/// movers within the radius of that stretch of the path are tested, and the doorways of the cells over it: a centre
/// passing in through one goes on in that cell. The walk ends at the first stretch that holds the earliest contact
/// found, so its cost grows with the cells crossed, not the landblock's size. A stretch in a landblock that is not
/// loaded (or off the world) stops the cast where it begins.
/// </para>
/// </remarks>
internal static partial class WorldCast
{
    private const float Size = PhysicsConstants.LandblockSize;
    private const double Column = PhysicsConstants.CellSize;

    /// <summary>Where the centre is while the cast walks: the landblock, the cell (−1 outdoors) and the fraction it got there.</summary>
    private struct Piece
    {
        public LandblockEntry Entry;
        public int Cell;
        public double From;
        public bool Done;

        /// <summary>
        /// How far beyond a portal's plane (metres) the centre may be and still pass through it at once: at the start, the
        /// world frame's rounding of the start (a cast from another's rounded answer); after a crossing, none (the next
        /// crossing must come later, so two portals meeting at an edge cannot hand the centre back and forth).
        /// </summary>
        public double Slack;
    }

    public static CastHit Run(in WorldFrame frame, ref Neighbourhood lands, in Place start, Vector3 from, Vector3 to, in CastOptions options)
    {
        var origin = new D3(start.Local.X, start.Local.Y, from.Z);
        var move = new D3((double)to.X - from.X, (double)to.Y - from.Y, (double)to.Z - from.Z);
        var ray = new SweptSphere(origin, move, options.Radius);
        float rounding = 2f * MathF.Max(Geometry.Spacing(MathF.Abs(from.X)), MathF.Max(Geometry.Spacing(MathF.Abs(from.Y)), Geometry.Spacing(MathF.Abs(from.Z))));
        var piece = new Piece { Entry = start.Entry, Cell = start.CellIndex, Slack = Math.Max(PhysicsConstants.EdgeTolerance, rounding) };
        var cast = new Walk(start.X, start.Y, options);
        for (int visit = 0; visit < PhysicsConstants.MaxCellVisits && !piece.Done; visit++)
        {
            if (piece.Cell >= 0)
            {
                cast.Indoors(ref ray, ref lands, ref piece);
            }
            else
            {
                cast.Outdoors(ref ray, ref lands, ref piece);
            }
        }

        if (!piece.Done && piece.From < ray.T)
        {
            // Out of visits: the rest of the path was not looked at, so the cast ends where the last piece began.
            ray.Stop(piece.From, -move * (1.0 / Math.Max(move.Length, double.Epsilon)), new ShapeName(SurfaceKind.None, 0));
        }

        double t = Math.Min(ray.T, 1.0);
        D3 centre = ray.At(t);
        (int lx, int ly, Vector2 local) = cast.Landblock(centre);
        uint cellId = piece.Cell >= 0 ? piece.Entry.Cells[piece.Cell].CellId : WorldFrame.OutdoorCellId(lx, ly, local);
        if (!ray.Found)
        {
            return new CastHit(false, 1f, to, to, Vector3.Zero, SurfaceKind.None, 0, cellId);
        }

        Vector3 position = frame.ToWorld(start.X, start.Y, new Vector2((float)centre.X, (float)centre.Y), (float)centre.Z);
        D3 touch = centre - (ray.Normal * ray.Radius);
        Vector3 point = frame.ToWorld(start.X, start.Y, new Vector2((float)touch.X, (float)touch.Y), (float)touch.Z);
        return new CastHit(true, (float)t, position, point, ray.Normal.ToVector3(), ray.Kind, ray.Id, cellId);
    }

    /// <summary>
    /// The fraction at which the centre passes through the portal's opening, out of its cell (<paramref name="outward"/>)
    /// or into it; +∞ when it does not before the end. With a <paramref name="slack"/>, a centre on the plane or beyond it
    /// by no more than that, moving through, passes at <paramref name="from"/>; without, only later than
    /// <paramref name="from"/>.
    /// </summary>
    private static double Crossing(in SweptSphere ray, PortalShape portal, D3 offset, double from, double slack, bool outward)
    {
        Vector3 n = portal.OutNormal;
        if (portal.Kind == PortalKind.Degenerate)
        {
            return double.PositiveInfinity;
        }

        var normal = new D3(n.X, n.Y, n.Z);
        D3 o = offset + new D3(portal.Origin.X, portal.Origin.Y, portal.Origin.Z);
        double d0 = D3.Dot(normal, ray.At(from) - o), rate = D3.Dot(normal, ray.Move);
        double sign = outward ? 1 : -1;
        (d0, rate) = (d0 * sign, rate * sign);
        if (!(rate > 0) || d0 > slack || (slack == 0 && d0 >= 0))
        {
            return double.PositiveInfinity; // moving away from it, along it, or already beyond
        }

        double t = from + Math.Max(-d0 / rate, 0.0);
        if (t > 1.0)
        {
            return double.PositiveInfinity;
        }

        D3 at = ray.At(t) - o;
        const double tol = PhysicsConstants.EdgeTolerance;
        if (portal.Kind == PortalKind.Horizontal)
        {
            return portal.ContainsXY((float)(at.X + o.X - offset.X), (float)(at.Y + o.Y - offset.Y)) ? t : double.PositiveInfinity;
        }

        double along = (portal.Tangent.X * at.X) + (portal.Tangent.Y * at.Y);
        double z = at.Z + o.Z;
        return along >= portal.TMin - tol && along <= portal.TMax + tol && z >= portal.ZMin - tol && z <= portal.ZMax + tol ? t : double.PositiveInfinity;
    }

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static int FloorDiv(int a, int b) => a >= 0 ? a / b : -((-a + b - 1) / b);

    /// <summary>A box of one landblock's frame, metres: seen from above and in height (empty when lo &gt; hi).</summary>
    private readonly record struct Box(Vector2 Lo, Vector2 Hi, float ZLo, float ZHi)
    {
        public static Box Empty => new(new Vector2(float.MaxValue), new Vector2(float.MinValue), float.MaxValue, float.MinValue);

        public bool IsEmpty => !(Lo.X <= Hi.X && Lo.Y <= Hi.Y && ZLo <= ZHi);

        /// <summary>The sphere's path from t0 to t1, in the frame at <paramref name="offset"/>, grown by its radius and a margin for rounding to floats.</summary>
        public static Box Of(in SweptSphere ray, double t0, double t1, D3 offset)
        {
            D3 a = ray.At(t0) - offset, b = ray.At(t1) - offset;
            double grow = ray.Radius + PhysicsConstants.CastBoxMargin;
            return new Box(
                new Vector2((float)(Math.Min(a.X, b.X) - grow), (float)(Math.Min(a.Y, b.Y) - grow)),
                new Vector2((float)(Math.Max(a.X, b.X) + grow), (float)(Math.Max(a.Y, b.Y) + grow)),
                (float)(Math.Min(a.Z, b.Z) - grow),
                (float)(Math.Max(a.Z, b.Z) + grow));
        }

        public bool Meets(Vector2 lo, Vector2 hi, float zLo, float zHi) =>
            lo.X <= Hi.X && hi.X >= Lo.X && lo.Y <= Hi.Y && hi.Y >= Lo.Y && zLo <= ZHi && zHi >= ZLo;

        public Box With(Box other) =>
            new(Vector2.Min(Lo, other.Lo), Vector2.Max(Hi, other.Hi), MathF.Min(ZLo, other.ZLo), MathF.Max(ZHi, other.ZHi));

        public Box Grown(float by) => new(Lo - new Vector2(by), Hi + new Vector2(by), ZLo - by, ZHi + by);

        public Box Within(in Box other) =>
            new(Vector2.Max(Lo, other.Lo), Vector2.Min(Hi, other.Hi), MathF.Max(ZLo, other.ZLo), MathF.Min(ZHi, other.ZHi));

        public Box Moved(Vector2 by) => new(Lo + by, Hi + by, ZLo, ZHi);

        /// <summary>The fractions, from <paramref name="from"/> on, at which the centre is in this box (the frame at <paramref name="offset"/>); null when never.</summary>
        public (double From, double To)? Span(in SweptSphere ray, D3 offset, double from)
        {
            D3 p = ray.Start - offset, d = ray.Move;
            double t0 = from, t1 = 1.0;
            Clip(p.X, d.X, Lo.X, Hi.X, ref t0, ref t1);
            Clip(p.Y, d.Y, Lo.Y, Hi.Y, ref t0, ref t1);
            Clip(p.Z, d.Z, ZLo, ZHi, ref t0, ref t1);
            return t0 <= t1 ? (t0, t1) : null;

            static void Clip(double p0, double dp, double lo, double hi, ref double t0, ref double t1)
            {
                if (dp == 0)
                {
                    if (p0 < lo || p0 > hi)
                    {
                        (t0, t1) = (1, 0);
                    }

                    return;
                }

                double a = (lo - p0) / dp, b = (hi - p0) / dp;
                (t0, t1) = (Math.Max(t0, Math.Min(a, b)), Math.Min(t1, Math.Max(a, b)));
            }
        }
    }
}
