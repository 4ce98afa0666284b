using System.Diagnostics.CodeAnalysis;
using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.Casting;

namespace AcDream.Core.Physics;

/// <summary>Casts through the world: where a sphere (a camera's) or a ray (a pointer's) first meets something.</summary>
public sealed partial class PhysicsEngine
{
    /// <summary>
    /// Sweeps a sphere (a ray with radius 0) from <see cref="CastRequest.From"/> along <see cref="CastRequest.Delta"/> and returns its first
    /// contact: terrain, a cell's wall, floor or ceiling, an object (wall, shell, floor or cylinder) or a mover, and the
    /// cell its centre is in there, found by following portals between cells and seams between landblocks.
    /// </summary>
    /// <remarks>
    /// <para>
    /// Positions are world metres; the contact is in closed form in double precision for the game's terrain triangles,
    /// polygons and cylinders (a cylinder's rim: the roots of a quartic, isolated and bisected to double precision).
    /// Polygons are two-sided and a polygon's face counts within 1e-6 m of its edges, so nothing passes a surface of zero
    /// thickness or the seam between two. On the spec's bilinear terrain a ray is exact and a sphere meets the ground at
    /// its lowest point. A sphere that starts within its radius of a polygon and moves into its plane is stopped at fraction
    /// 0 with the polygon's normal; one moving along the plane or away is free of it (a sphere gliding over a floor of many
    /// triangles); a start exactly on a polygon's plane is free of it either way (a ray up from the feet on the terrain or a
    /// cell's floor; an object's polygons are met at their vertices placed in double precision, up to 7.6e-6 m from the
    /// float plane a mover's answer stands on, so start a cast a little above feet on an object's floor). A cylinder
    /// decides by its nearest point. A cast of zero
    /// length meets nothing. As <c>Resolve</c>, it takes a delta: the end is <c>From + Delta</c>, rounded to floats.
    /// </para>
    /// <para>
    /// Outdoors the sphere meets the terrain, outdoor objects (buildings by their shells) and the walls of buildings'
    /// cells; its centre passing in through a doorway goes on in that cell. In a cell it meets the cell's and its
    /// portal neighbours' polygons and objects (and, near a door, what stands outside the door); its centre passing out
    /// through a portal goes on beyond it. A start exactly on a surface moving off it (a ray up from the feet) is free of it. The movers committed last (<see cref="Movers"/>) are met by their walls, as
    /// <see cref="CastRequest.Options"/> filters them (and <see cref="CastRequest.MoverId"/> passes); a mover in a landblock that is neither the start's nor next to it is not. Of
    /// the movers it looks only at those filed near each stretch of its path.
    /// The cast reads each landblock of the 3 × 3 around its start once (one farther away, afresh each time), allocates
    /// nothing (after a thread's first cast with movers near, which makes the thread's record of them), and never
    /// changes the engine.
    /// </para>
    /// <para>
    /// A cast from a landblock that is not loaded returns a contact at fraction 0 with kind <see cref="SurfaceKind.None"/>;
    /// one whose path reaches land not loaded (or the world's edge) stops there the same way. A cast that meets nothing
    /// returns the end with fraction 1. It enters at most <see cref="PhysicsConstants.MaxCellVisits"/>
    /// pieces (a cell, or a walk outdoors); one that would need more ends where its last piece began, the same way.
    /// </para>
    /// </remarks>
    /// <param name="request">Where it starts (world metres), its cell (<c>0xXXYYCCCC</c>; an outdoor number, 0 included, is recomputed from the position), the centre's displacement, the radius (metres, 0 to <see cref="PhysicsConstants.MaxCastRadius"/>), filters and the mover it ignores. The start's cell is not always the cell <c>Resolve</c> names for a mover whose start is above its feet: a body in the air over a floor opening is in the cell below, a pivot over its head may be in the cell above; find it with <see cref="FindCell"/>.</param>
    /// <exception cref="ArgumentOutOfRangeException">The radius is more than <see cref="PhysicsConstants.MaxCastRadius"/> (named <c>request</c>).</exception>
    /// <exception cref="ArgumentException">A position or the delta is not finite (or the end overflows), the radius is negative or not finite, the cell id is not a cell of the world, or an indoor cell is not in its loaded landblock; each named <c>request</c>, with the field.</exception>
    public CastHit Cast(in CastRequest request) => _recorder is null ? Casted(in request) : Recorded(in request);

    /// <summary>
    /// The cast itself. The preamble is written out, as every query's: measured, a generic form cost the camera's cast 7–10 %.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private CastHit Casted(in CastRequest request)
    {
        var body = new Casting(in request);
        body.Validate();
        var lands = new Neighbourhood(_registry);
        return _movers.Any && body.Meet(ref lands, _movers, in _frame)
            ? Held<Casting, CastHit>(ref lands, in body)
            : body.Run(this, ref lands, held: false);
    }

    /// <summary>
    /// A cast with a recorder set, out of line: the unrecorded cast then returns its answer straight (measured, handing the
    /// recorder a reference to the answer in the same method made the camera's cast about 5 % slower).
    /// </summary>
    [MethodImpl(MethodImplOptions.NoInlining)]
    private CastHit Recorded(in CastRequest request)
    {
        CastHit hit = Casted(in request);
        _recorder?.Cast(in request, in hit);
        return hit;
    }

    /// <summary>
    /// The cast's own part: checked, the movers near its path held (<see cref="Neighbourhood.MeetAlong"/>), then its walk
    /// from the start's cell; a start whose land is not loaded is stopped where it is.
    /// </summary>
    private readonly ref struct Casting(ref readonly CastRequest request) : IHeldBody<CastHit>
    {
        private readonly ref readonly CastRequest _request = ref request;

        public void Validate()
        {
            ref readonly CastRequest r = ref _request;
            Vector3 from = r.From, to = from + r.Delta;
            CastOptions options = r.Options;
            if (!(Geometry.IsFinite(from) && Geometry.IsFinite(to) && options.Radius >= 0f && options.Radius <= PhysicsConstants.MaxCastRadius && CellIds.IsCellOfTheWorld(r.FromCellId)))
            {
                ThrowInvalidCast(in r);
            }
        }


        public bool Meet(ref Neighbourhood lands, MoverRegistry movers, in WorldFrame frame)
        {
            ref readonly CastRequest r = ref _request;
            Vector3 move = (r.From + r.Delta) - r.From;
            float reach = MathF.Abs(move.X) + MathF.Abs(move.Y) + r.Options.Radius + PhysicsConstants.TouchReach;
            return lands.MeetAlong(movers, in frame, r.From, r.FromCellId, reach, r.MoverId);
        }

        public CastHit Run(PhysicsEngine engine, ref Neighbourhood lands, bool held)
        {
            ref readonly CastRequest r = ref _request;
            Vector3 from = r.From, to = from + r.Delta;
            CastOptions options = r.Options;
            if (!Locator.TryFind(engine._frame, ref lands, from, r.FromCellId, out Place start, nameof(request)))
            {
                // The land under the start is not loaded: stopped where it is, in its cell (an outdoor one found from the position).
                Vector3 back = from == to ? Vector3.Zero : Vector3.Normalize(from - to);
                engine._frame.Locate(from, r.FromCellId, out int x, out int y, out Vector2 local);
                uint cell = CellIds.IsIndoor(r.FromCellId) ? r.FromCellId : WorldFrame.OutdoorCellId(x, y, local);
                return new CastHit(true, 0f, from, from - (back * options.Radius), back, SurfaceKind.None, 0, cell);
            }

            return WorldCast.Run(in engine._frame, ref lands, in start, from, to, in options);
        }
    }

    [DoesNotReturn]
    [MethodImpl(MethodImplOptions.NoInlining)]
    private static void ThrowInvalidCast(in CastRequest request)
    {
        float radius = request.Options.Radius;
        uint cellId = request.FromCellId;
        if (!Geometry.IsFinite(request.From))
        {
            throw new ArgumentException($"request.From {request.From} must be finite (cell 0x{cellId:X8}).", nameof(request));
        }

        if (!Geometry.IsFinite(request.Delta))
        {
            throw new ArgumentException($"request.Delta {request.Delta} must be finite (cell 0x{cellId:X8}).", nameof(request));
        }

        if (!Geometry.IsFinite(request.From + request.Delta))
        {
            throw new ArgumentException($"request.From {request.From} + request.Delta {request.Delta} overflows a float (cell 0x{cellId:X8}).", nameof(request));
        }

        if (!(float.IsFinite(radius) && radius >= 0f))
        {
            throw new ArgumentException($"request.Options.Radius {radius} must be finite and at least 0 metres (cell 0x{cellId:X8}).", nameof(request));
        }

        if (radius > PhysicsConstants.MaxCastRadius)
        {
            throw new ArgumentOutOfRangeException(nameof(request), radius, $"request.Options.Radius {radius} (cell 0x{cellId:X8}) is more than the largest cast radius, {PhysicsConstants.MaxCastRadius} metres (PhysicsConstants.MaxCastRadius).");
        }

        throw new ArgumentException($"request.FromCellId 0x{cellId:X8} is not a cell of the world (0x0000..0x0040 outdoors, 0x0100..0xFFFD indoors, landblock X and Y below 0xFF).", nameof(request));
    }
}
