using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using AcDream.Core.Physics.Surfaces;

namespace AcDream.Core.Physics.Body;

/// <summary>
/// What a rising body's top meets: the lowest point of any wall polygon, cylinder or floor (seen from below) over
/// its disc, above its top. Landblock-local metres; allocation-free.
/// </summary>
/// <remarks>
/// The lowest point of a planar polygon over a disc is the lowest of: its vertices inside the disc, the points
/// where its edges cross the disc's rim, and the disc's lowest point on the polygon's plane when that lies
/// inside the polygon (a linear function over the polygon cut to the disc is lowest on that set's boundary,
/// made of the polygon's edges inside the disc and arcs of the rim inside the polygon).
/// </remarks>
internal static class Overhead
{
    /// <summary>A polygon whose unit normal's Z is smaller than this is vertical for the disc's lowest point: its lowest point over the disc is on its outline.</summary>
    private const float VerticalNormalZ = 1e-3f;

    /// <summary>
    /// Lowers <paramref name="hit"/> to what of <paramref name="walls"/> (their frame <paramref name="offset"/> from the
    /// body's) is lowest over the disc of <paramref name="rise"/> within its rise.
    /// </summary>
    public static void Walls(CellWalls walls, Vector2 offset, in BodyRise rise, ref CeilingHit hit)
    {
        Vector2 lo = rise.Centre - offset - new Vector2(rise.Radius), hi = rise.Centre - offset + new Vector2(rise.Radius);
        if (walls.Min.X > hi.X || walls.Max.X < lo.X || walls.Min.Y > hi.Y || walls.Max.Y < lo.Y || walls.ZMax <= rise.Top || walls.ZMin >= hit.Z)
        {
            return;
        }

        Vector128<float> query = WallExtent.Query(lo, hi);
        ReadOnlySpan<WallExtent> extents = walls.Extents;
        Vector2 c = rise.Centre - offset;
        for (int i = 0; i < extents.Length; i++)
        {
            if (!extents[i].Meets(query, rise.Top, hit.Z))
            {
                continue;
            }

            ref readonly WallPolygon wall = ref walls.Polygons[i];
            if (wall.IsUpright)
            {
                // Upright: its outline seen from above at every height, so it is over the disc from its bottom up.
                float reach = rise.Radius + wall.Radius;
                if (Geometry.DistanceSquaredToSegment(c, wall.A, wall.B) < reach * reach)
                {
                    Keep(wall.ZMin, -Vector3.UnitZ, rise.Top, ref hit);
                }

                continue;
            }

            if (LowestOver(walls.Vertices.AsSpan(wall.First, wall.Count), c, rise.Radius, out float z, out Vector3 normal))
            {
                Keep(z, normal, rise.Top, ref hit);
            }
        }
    }

    /// <summary>Lowers <paramref name="hit"/> to the floors among <paramref name="floors"/> (their undersides) that are lowest over the disc within its rise.</summary>
    public static void Floors(ReadOnlySpan<FloorTriangle> floors, Vector2 offset, in BodyRise rise, ref CeilingHit hit)
    {
        Vector2 c = rise.Centre - offset;
        float r = rise.Radius;
        Span<Vector3> corners = stackalloc Vector3[3];
        foreach (ref readonly FloorTriangle t in floors)
        {
            if (t.ZMax <= rise.Top || t.ZMin >= hit.Z || t.Min.X > c.X + r || t.Max.X < c.X - r || t.Min.Y > c.Y + r || t.Max.Y < c.Y - r)
            {
                continue;
            }

            (corners[0], corners[1], corners[2]) = (new Vector3(t.A, t.ZAt(t.A)), new Vector3(t.B, t.ZAt(t.B)), new Vector3(t.C, t.ZAt(t.C)));
            if (LowestOver(corners, c, r, out float z, out _))
            {
                Keep(z, -t.Normal, rise.Top, ref hit);
            }
        }
    }

    /// <summary>
    /// Raises <paramref name="hit"/> to the highest point over the disc of <paramref name="fall"/> (its centre and radius; its
    /// band from <see cref="BodyRise.Top"/> down to <c>hit.Z</c>) of the faces among <paramref name="walls"/> too steep to
    /// stand on but not to land on (unit normal Z above <see cref="PhysicsConstants.LandingZ"/>, below <see cref="PhysicsConstants.FloorZ"/>,
    /// facing up): what a falling body's feet meet on a steep roof or slope. <c>hit.Normal</c>: the face's, up.
    /// </summary>
    [SkipLocalsInit] // the buffer is written before it is read
    public static void Steep(CellWalls walls, Vector2 offset, in BodyRise fall, ref CeilingHit hit)
    {
        Vector2 c = fall.Centre - offset;
        var r = new Vector2(fall.Radius);
        if (!walls.HasSteep || walls.Min.X > c.X + r.X || walls.Max.X < c.X - r.X || walls.Min.Y > c.Y + r.Y || walls.Max.Y < c.Y - r.Y || walls.ZMax <= hit.Z || walls.ZMin >= fall.Top)
        {
            return;
        }

        Vector128<float> query = WallExtent.Query(c - r, c + r);
        ReadOnlySpan<WallExtent> extents = walls.Extents;
        Span<Vector3> flipped = stackalloc Vector3[PhysicsConstants.MaxWallPolygonVertices];
        for (int i = 0; i < extents.Length; i++)
        {
            ref readonly WallPolygon wall = ref walls.Polygons[i];
            if (wall.IsUpright || !extents[i].Meets(query, hit.Z, fall.Top))
            {
                continue;
            }

            // The highest point over the disc: the lowest of the polygon turned upside down.
            ReadOnlySpan<Vector3> v = walls.Vertices.AsSpan(wall.First, wall.Count);
            for (int k = 0; k < v.Length; k++)
            {
                flipped[k] = v[k] with { Z = -v[k].Z };
            }

            if (LowestOver(flipped[..v.Length], c, fall.Radius, out float lowest, out Vector3 down) && -down.Z > PhysicsConstants.LandingZ && -down.Z < PhysicsConstants.FloorZ
                && -lowest <= fall.Top && -lowest > hit.Z)
            {
                (hit.Z, hit.Normal, hit.Source) = (-lowest, new Vector3(down.X, down.Y, -down.Z), hit.Current);
            }
        }
    }

    /// <summary>
    /// The highest top of the upright cylinders of <paramref name="walls"/> (a mover's, placed) under the falling disc
    /// <paramref name="fall"/> in the band above <c>hit.Z</c>: a body does not stand on a mover. Held on its top in the air,
    /// it slides off outward, as off a face of normal Z 0.5 (between <see cref="PhysicsConstants.LandingZ"/> and
    /// <see cref="PhysicsConstants.FloorZ"/>) turned away from the axis (+X when over it).
    /// </summary>
    public static void Tops(CellWalls walls, Vector2 offset, in BodyRise fall, ref CeilingHit hit)
    {
        const float rise = 0.5f, run = 0.8660254f; // a normal 60° from the vertical
        Vector2 c = fall.Centre - offset;
        foreach (ref readonly WallPolygon w in walls.Polygons.AsSpan())
        {
            float reach = fall.Radius + w.Radius;
            Vector2 d = c - w.A;
            if (w.Radius > 0f && w.ZMax > hit.Z && w.ZMax <= fall.Top && d.LengthSquared() < reach * reach)
            {
                Vector2 away = d == Vector2.Zero ? Vector2.UnitX : Vector2.Normalize(d);
                (hit.Z, hit.Normal, hit.Source) = (w.ZMax, new Vector3(away * run, rise), hit.Current);
            }
        }
    }

    /// <summary>
    /// The lowest Z of polygon <paramref name="v"/> (landblock-local) over the open disc of centre <paramref name="c"/> and
    /// radius <paramref name="r"/> seen from above, with the polygon's unit normal turned to face down (a vertical one's:
    /// straight down). False when the polygon is not over the disc.
    /// </summary>
    public static bool LowestOver(ReadOnlySpan<Vector3> v, Vector2 c, float r, out float lowest, out Vector3 normal)
    {
        float r2 = r * r;
        lowest = float.PositiveInfinity;
        Vector3 newell = Vector3.Zero;
        for (int i = 0, j = v.Length - 1; i < v.Length; j = i++)
        {
            Vector3 a = v[j], b = v[i];
            newell += new Vector3((a.Y - b.Y) * (a.Z + b.Z), (a.Z - b.Z) * (a.X + b.X), (a.X - b.X) * (a.Y + b.Y));
            var ab = new Vector2(b.X - a.X, b.Y - a.Y);
            var ca = new Vector2(a.X - c.X, a.Y - c.Y);
            if (Vector2.Dot(ca, ca) < r2)
            {
                lowest = MathF.Min(lowest, a.Z);
            }

            // Where the edge crosses the rim: |ca + t·ab|² = r².
            float qa = Vector2.Dot(ab, ab);
            if (qa == 0f)
            {
                continue;
            }

            float qb = Vector2.Dot(ca, ab), qc = Vector2.Dot(ca, ca) - r2;
            float disc = (qb * qb) - (qa * qc);
            if (!(disc > 0f))
            {
                continue;
            }

            float root = MathF.Sqrt(disc);
            float t0 = (-qb - root) / qa, t1 = (-qb + root) / qa;
            if (t0 >= 0f && t0 <= 1f)
            {
                lowest = MathF.Min(lowest, a.Z + ((b.Z - a.Z) * t0));
            }

            if (t1 >= 0f && t1 <= 1f)
            {
                lowest = MathF.Min(lowest, a.Z + ((b.Z - a.Z) * t1));
            }
        }

        float length = newell.Length();
        normal = length > 0f ? newell / length : -Vector3.UnitZ;
        normal = normal.Z > 0f ? -normal : normal;
        if (MathF.Abs(normal.Z) > VerticalNormalZ)
        {
            // The disc's lowest point on the polygon's plane: down its slope from the centre, or the centre under a level one.
            var gradient = new Vector2(-normal.X / normal.Z, -normal.Y / normal.Z);
            float slope = gradient.Length();
            Vector2 p = slope > 0f ? c - (gradient * (r * 0.999999f / slope)) : c;
            if (Geometry.InsidePolygonXY(v, p))
            {
                lowest = MathF.Min(lowest, v[0].Z + Vector2.Dot(gradient, p - new Vector2(v[0].X, v[0].Y)));
            }
        }

        return lowest < float.PositiveInfinity;
    }

    /// <summary>Keeps a surface whose lowest point over the disc is <paramref name="z"/> when it is above the top (less the contact tolerance: one the top already touches counts) and lower than the one so far.</summary>
    private static void Keep(float z, Vector3 normal, float top, ref CeilingHit hit)
    {
        if (z >= top - PhysicsConstants.ContactTolerance && (z < hit.Z || (z == hit.Z && hit.Source.Kind == SurfaceKind.None)))
        {
            (hit.Z, hit.Normal, hit.Source) = (z, normal, hit.Current);
        }
    }
}

/// <summary>A rising body: its disc (<see cref="Centre"/>, <see cref="Radius"/>) and its top's Z, landblock-local metres.</summary>
internal readonly record struct BodyRise(Vector2 Centre, float Radius, float Top);

/// <summary>
/// The running answer of a rise: the lowest surface over the disc so far (<see cref="Z"/>; the highest the top may reach
/// when none), its unit normal facing down, and whose it is.
/// </summary>
internal struct CeilingHit
{
    public float Z;
    public Vector3 Normal;
    public WallSource Source;

    /// <summary>Whose surfaces are being read now.</summary>
    public WallSource Current;
}
