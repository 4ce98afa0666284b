using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>
/// A portal polygon prepared for crossing tests, in landblock-local metres. A doorway (vertical)
/// is crossed within the rectangle that bounds it in its own plane (whether a polygon covers it is
/// decided by its own outline); a floor or ceiling opening (horizontal) by its outline seen from above.
/// </summary>
internal sealed class PortalShape
{
    private readonly Vector2[] _outline;

    /// <summary>For a vertical portal: its polygon in its own plane, (along <see cref="Tangent"/> from <see cref="Origin"/>, Z); an arch is not its bounding rectangle.</summary>
    private Vector2[] Profile { get; init; } = [];

    /// <summary>A vertical portal's vertices as (along <see cref="Tangent"/> from <see cref="Origin"/>, Z); empty for the other kinds.</summary>
    public ReadOnlySpan<Vector2> ProfilePoints => Profile;

    private PortalShape(PortalKind kind, Vector3 origin, Vector3 outNormal, Vector2 tangent, float tMin, float tMax, float zMin, float zMax, Vector2[] outline)
    {
        Kind = kind;
        Origin = origin;
        OutNormal = outNormal;
        Tangent = tangent;
        TMin = tMin;
        TMax = tMax;
        ZMin = zMin;
        ZMax = zMax;
        _outline = outline;
    }

    public PortalKind Kind { get; }

    /// <summary>Bounds of the polygon seen from above, landblock-local metres.</summary>
    public Vector2 BoundsMin { get; private init; }

    public Vector2 BoundsMax { get; private init; }

    /// <summary>Centroid (mean of the vertices).</summary>
    public Vector3 Origin { get; }

    /// <summary>Unit normal pointing out of the owning cell; zero when degenerate.</summary>
    public Vector3 OutNormal { get; }

    /// <summary>Vertical portals: unit horizontal direction along the opening.</summary>
    public Vector2 Tangent { get; }

    /// <summary>Vertical portals: extent along <see cref="Tangent"/>, relative to <see cref="Origin"/>.</summary>
    public float TMin { get; }

    public float TMax { get; }

    /// <summary>Lowest and highest Z of the polygon.</summary>
    public float ZMin { get; }

    public float ZMax { get; }

    /// <summary>
    /// Prepares a portal from its landblock-local vertices. <paramref name="cellOnPositiveSide"/>
    /// says which side of the winding normal the owning cell lies on (the dat's PortalSide bit).
    /// </summary>
    public static PortalShape Create(ReadOnlySpan<Vector3> vertices, bool cellOnPositiveSide)
    {
        Vector3 origin = Vector3.Zero;
        float zMin = float.MaxValue, zMax = float.MinValue;
        foreach (Vector3 v in vertices)
        {
            origin += v;
            zMin = MathF.Min(zMin, v.Z);
            zMax = MathF.Max(zMax, v.Z);
        }

        origin /= vertices.Length;
        Vector2 boundsMin = new(float.MaxValue), boundsMax = new(float.MinValue);
        foreach (Vector3 v in vertices)
        {
            boundsMin = Vector2.Min(boundsMin, new Vector2(v.X, v.Y));
            boundsMax = Vector2.Max(boundsMax, new Vector2(v.X, v.Y));
        }

        Vector3 normal = Geometry.NewellNormal(vertices, origin);
        if (normal == Vector3.Zero)
        {
            return new PortalShape(PortalKind.Degenerate, origin, Vector3.Zero, default, 0f, 0f, zMin, zMax, []) { BoundsMin = boundsMin, BoundsMax = boundsMax };
        }

        Vector3 outNormal = cellOnPositiveSide ? -normal : normal;
        if (MathF.Abs(outNormal.Z) >= PhysicsConstants.HorizontalPortalNormalZ)
        {
            var outline = new Vector2[vertices.Length];
            for (int i = 0; i < vertices.Length; i++)
            {
                outline[i] = new Vector2(vertices[i].X, vertices[i].Y);
            }

            return new PortalShape(PortalKind.Horizontal, origin, outNormal, default, 0f, 0f, zMin, zMax, outline) { BoundsMin = boundsMin, BoundsMax = boundsMax };
        }

        var tangent = Vector2.Normalize(new Vector2(-outNormal.Y, outNormal.X));
        float tMin = float.MaxValue, tMax = float.MinValue;
        foreach (Vector3 v in vertices)
        {
            float t = Vector2.Dot(tangent, new Vector2(v.X - origin.X, v.Y - origin.Y));
            tMin = MathF.Min(tMin, t);
            tMax = MathF.Max(tMax, t);
        }

        var profile = new Vector2[vertices.Length];
        for (int i = 0; i < vertices.Length; i++)
        {
            profile[i] = new Vector2(Vector2.Dot(tangent, new Vector2(vertices[i].X - origin.X, vertices[i].Y - origin.Y)), vertices[i].Z);
        }

        return new PortalShape(PortalKind.Vertical, origin, outNormal, tangent, tMin, tMax, zMin, zMax, []) { BoundsMin = boundsMin, BoundsMax = boundsMax, Profile = profile };
    }

    /// <summary>
    /// For a vertical portal: the fraction t (0..1) along the horizontal move p0 → p1, made with the
    /// feet at <paramref name="z"/>, where the mover passes out through the doorway; or −1 when the
    /// move ends on the cell's side of the portal plane or passes beside, above or more than
    /// <paramref name="stepUp"/> below the opening. <paramref name="crossesPlane"/> says whether the
    /// move ends beyond the plane at all: true with −1 means it went through the wall beside the opening.
    /// </summary>
    public float CrossingFraction(Vector2 p0, Vector2 p1, float z, float stepUp, out bool crossesPlane)
    {
        var o = new Vector3(p0.X - Origin.X, p0.Y - Origin.Y, z - Origin.Z);
        float d0 = Vector3.Dot(OutNormal, o);
        float d1 = d0 + (OutNormal.X * (p1.X - p0.X)) + (OutNormal.Y * (p1.Y - p0.Y));
        crossesPlane = d1 > 0f && d1 > d0;
        if (!crossesPlane)
        {
            return -1f;
        }

        float t = d0 >= 0f ? 0f : -d0 / (d1 - d0);
        return WithinOpening(p0 + ((p1 - p0) * t), z, stepUp) ? t : -1f;
    }

    /// <summary>
    /// For a vertical portal: the fraction t (0..1) along p0 → p1 where a mover outside the cell
    /// passes in through the doorway (ending on the plane, within
    /// <see cref="PhysicsConstants.EdgeTolerance"/>, or past it), with the same opening test as
    /// <see cref="CrossingFraction"/>; or −1.
    /// </summary>
    public float InwardCrossingFraction(Vector2 p0, Vector2 p1, float z, float stepUp)
    {
        var o = new Vector3(p0.X - Origin.X, p0.Y - Origin.Y, z - Origin.Z);
        float d0 = Vector3.Dot(OutNormal, o);
        float d1 = d0 + (OutNormal.X * (p1.X - p0.X)) + (OutNormal.Y * (p1.Y - p0.Y));
        const float tol = PhysicsConstants.EdgeTolerance;
        if (!(d0 >= -tol) || !(d1 <= tol) || !(d1 < d0))
        {
            return -1f;
        }

        float t = d0 <= 0f ? 0f : Math.Min(d0 / (d0 - d1), 1f);
        return WithinOpening(p0 + ((p1 - p0) * t), z, stepUp) ? t : -1f;
    }

    /// <summary>
    /// For a vertical portal: the unit normal of the wall it is cut in, facing into the owning cell
    /// (horizontal). What a move that crosses the portal's plane beside the opening runs into.
    /// </summary>
    public Vector3 WallNormal => new(-Tangent.Y, Tangent.X, 0f); // the tangent turned a quarter back: −(horizontal out-normal)

    /// <summary>
    /// For a vertical portal: how far (metres) <paramref name="p"/> lies beyond the portal's plane,
    /// out of the owning cell, measured along the horizontal part of the out-normal (negative: on the
    /// cell's side).
    /// </summary>
    public float HorizontalDistance(Vector2 p) =>
        (OutNormal.X * (p.X - Origin.X)) + (OutNormal.Y * (p.Y - Origin.Y));

    /// <summary>Whether a point of the portal's plane, with the feet at <paramref name="z"/>, is in the opening.</summary>
    private bool WithinOpening(Vector2 q, float z, float stepUp)
    {
        float along = Vector2.Dot(Tangent, new Vector2(q.X - Origin.X, q.Y - Origin.Y));
        const float tol = PhysicsConstants.EdgeTolerance;
        return along >= TMin - tol && along <= TMax + tol && z <= ZMax + tol && z >= ZMin - stepUp - tol;
    }

    /// <summary>
    /// For a horizontal portal: whether (x, y) is inside the opening seen from above (edges within
    /// <see cref="PhysicsConstants.EdgeTolerance"/> count as inside).
    /// </summary>
    public bool ContainsXY(float x, float y) => Geometry.PolygonContains(_outline, new Vector2(x, y), PhysicsConstants.EdgeTolerance);

    /// <summary>
    /// For a horizontal portal: whether the horizontal move <paramref name="p0"/> → <paramref name="p1"/> passes
    /// over or under the opening seen from above: an end inside it (edges within
    /// <see cref="PhysicsConstants.EdgeTolerance"/> counting) or the segment crossing its outline.
    /// </summary>
    public bool SegmentTouchesXY(Vector2 p0, Vector2 p1)
    {
        if (ContainsXY(p0.X, p0.Y) || ContainsXY(p1.X, p1.Y))
        {
            return true;
        }

        Vector2 d = p1 - p0;
        for (int i = 0, j = _outline.Length - 1; i < _outline.Length; j = i++)
        {
            Vector2 a = _outline[j], e = _outline[i] - a;
            float denominator = (d.X * e.Y) - (d.Y * e.X);
            if (denominator == 0f)
            {
                continue; // parallel: an end inside, or the crossing of another edge, decides
            }

            Vector2 w = a - p0;
            float s = ((w.X * e.Y) - (w.Y * e.X)) / denominator, u = ((w.X * d.Y) - (w.Y * d.X)) / denominator;
            if (s >= 0f && s <= 1f && u >= 0f && u <= 1f)
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>
    /// Whether a physics polygon (landblock-local vertices, <paramref name="centre"/> their mean) covers
    /// this portal: every vertex within <see cref="PhysicsConstants.DoorwayCoverTolerance"/> of the
    /// portal's plane and the centre inside the portal's polygon (a doorway's own outline in its plane, an
    /// opening's seen from above). Such a polygon is the doorway itself, not a wall.
    /// </summary>
    public bool Covers(ReadOnlySpan<Vector3> polygon, Vector3 centre)
    {
        if (Kind == PortalKind.Degenerate)
        {
            return false;
        }

        foreach (Vector3 v in polygon)
        {
            if (MathF.Abs(Vector3.Dot(OutNormal, v - Origin)) > PhysicsConstants.DoorwayCoverTolerance)
            {
                return false;
            }
        }

        if (Kind == PortalKind.Horizontal)
        {
            return ContainsXY(centre.X, centre.Y);
        }

        // Inside the doorway's own polygon (not its bounding rectangle: the wall over an arch's shoulders is a wall).
        float along = Vector2.Dot(Tangent, new Vector2(centre.X - Origin.X, centre.Y - Origin.Y));
        return Geometry.PolygonContains(Profile, new Vector2(along, centre.Z), PhysicsConstants.EdgeTolerance);
    }

    /// <summary>For a horizontal portal: its outline seen from above, in winding order (empty otherwise).</summary>
    public ReadOnlySpan<Vector2> Outline => _outline;

    /// <summary>For a horizontal portal: Z of its plane at (x, y).</summary>
    public float PlaneZ(float x, float y) =>
        Origin.Z - (((OutNormal.X * (x - Origin.X)) + (OutNormal.Y * (y - Origin.Y))) / OutNormal.Z);
}

/// <summary>How a portal polygon is oriented.</summary>
internal enum PortalKind
{
    /// <summary>A doorway: crossed by walking through its plane.</summary>
    Vertical,

    /// <summary>An opening in a floor or ceiling: entered by standing over it.</summary>
    Horizontal,

    /// <summary>Zero area: no crossing test applies.</summary>
    Degenerate,
}
