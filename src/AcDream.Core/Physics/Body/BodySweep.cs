using System.Numerics;

namespace AcDream.Core.Physics.Body;

/// <summary>
/// The body's horizontal move among walls, in closed form: an upright cylinder of radius r sweeps
/// from p along d; each wall polygon, cut to the height band the cylinder meets walls in (from the
/// step height above the feet to the top), seen from above is a set of edges, and the cylinder
/// touches an edge when its centre comes within r of it. The time of impact against an edge is the
/// earliest of the centre's line reaching the edge's two offset lines (within the edge) and its two
/// end circles: no sub-steps, so nothing is skipped at any speed or wall thickness. At contact the
/// rest of the move continues along the wall (projected onto it), up to
/// <see cref="PhysicsConstants.MaxBodyContacts"/> contacts; a second wall the slide would push into
/// (a concave corner) stops it. All in one landblock's frame (landblock-local metres); allocation-free.
/// </summary>
internal static partial class BodySweep
{
    /// <summary>
    /// A move that approaches a wall it touches by less than this fraction of its length moves along
    /// it, not into it: what a slide's projection onto the wall leaves is float residue of either sign,
    /// and taking it for a new contact stopped a body sliding along one wall as if in a corner.
    /// </summary>
    private const float ParallelTolerance = 1e-5f;

    /// <summary>
    /// A slide that points into the wall touched before by more than this fraction of its length is in
    /// a concave corner; less is the same wall touched again (a wall's end, whose normal the float
    /// rounding of the position turns by ~1e-5 rad between two touches).
    /// </summary>
    private const float ConcaveTolerance = 1e-3f;

    /// <summary>
    /// Slides a body (<paramref name="move"/>: its contact radius, start, move and band) among the walls of
    /// <paramref name="walls"/>, writing the path's corners to <paramref name="points"/> (landblock-local;
    /// room for <see cref="PhysicsConstants.MaxBodyContacts"/> + 2). A body that starts closer to a wall
    /// than the contact radius by more than its sink (and less than four times it) is first put back at
    /// the contact radius.
    /// </summary>
    /// <remarks>
    /// Why the push back: every answer is rounded to the world frame, and a body moving along a wall
    /// with the same delta frame after frame is rounded the same way each time, so without it the body
    /// sank into the wall by up to half a float spacing per frame (1 mm after 350 frames in a centred
    /// frame, its whole radius after 470 at the far corner of the global one). The sink is
    /// half the skin the contact radius keeps beyond the body's: what one call's rounding may take stays
    /// inside the skin, and a body at rest in a corner (sunk by less) is not moved, so it stays bit for
    /// bit. Deeper overlaps are not this rounding (a body placed in a wall by its caller) and are left
    /// alone; so is a push back into another wall (a narrow wedge).
    /// </remarks>
    public static void Slide(in WallSet walls, in BodyMove move, Span<Vector2> points, ref BodyPath path)
    {
        Vector2 p = move.P, d = move.D;
        float sink = move.Sink;
        points[0] = p;
        path.Count = 1;
        float together = MathF.Max(PhysicsConstants.ContactTolerance, 2f * sink);
        Vector2 position = p, rest = d, previous = default, unprojected = d;
        for (int contact = 0; /* Stryker disable once Equality : the last turn only stops the slide, as ending the loop does */ contact <= PhysicsConstants.MaxBodyContacts; contact++)
        {
            if (rest == Vector2.Zero)
            {
                break;
            }

            float t = 1f;
            Vector2 normal = default, lift = default; // (lift: out of a mover's solid the body starts in, see WallHit.Lift)
            WallSource wall = default;
            if (contact < PhysicsConstants.MaxBodyContacts)
            {
                var hit = WallHit.None;
                walls.Sweep(move.At(position, rest), ref hit);
                (t, normal, wall) = (hit.T, hit.Normal, hit.Source);
                lift = hit.Source == hit.DeepSource ? hit.Lift : default; // (out of the solid it slides along, never another's)
                if (contact == 0 && hit.Depth > sink && hit.Depth < 4f * sink)
                {
                    // Sunk into the skin by rounding: back out to the contact radius, unless that pushes
                    // the body into another wall.
                    Vector2 pushed = position + (hit.Outward * hit.Depth);
                    var pushedHit = WallHit.None;
                    walls.Sweep(move.At(pushed, rest), ref pushedHit);
                    if (pushedHit.Depth <= sink)
                    {
                        position = pushed;
                        points[path.Count++] = position;
                        path.Contacts++;
                        (path.Normal, path.Wall) = (hit.Outward, hit.DeepSource);
                        (t, normal, wall) = (pushedHit.T, pushedHit.Normal, pushedHit.Source);
                    }
                }
            }
            else
            {
                rest = Vector2.Zero; // out of contacts: stop at the last one
                // Stryker disable once Statement : going on adds the last corner again (a leg of no length) and stops
                break;
            }

            if (t >= 1f)
            {
                position += rest;
                points[path.Count++] = position;
                break;
            }

            float travelled = t * rest.Length();
            if (/* Stryker disable once Equality : at 0 it adds the corner it is at again (a leg of no length) */ t > 0f)
            {
                position += rest * t;
                points[path.Count++] = position;
            }

            path.Contacts++;
            (path.Normal, path.Wall) = (normal, wall);
            rest *= 1f - t;
            if (contact > 0 && travelled < together)
            {
                // Met together with the wall before (within the contact tolerance, or the skin, whose
                // rounding decides the order of contacts that close): the slide along this wall alone is
                // the one that can clear the other (projected in turn, the slide went along the wrong
                // wall, 9 cm astray beside a door jamb); if it does not, the body is wedged.
                unprojected *= 1f - t;
                Vector2 alone = Along(unprojected, normal);
                if (Vector2.Dot(alone, previous) < -ConcaveTolerance * alone.Length())
                {
                    break;
                }

                rest = alone + lift;
            }
            else
            {
                unprojected = rest;
                rest = Along(rest, normal);
                if (lift != default)
                {
                    rest += lift; // (added only when there is one: a slide with no mover keeps its bits)
                }
                if (contact > 0 && Blocked(rest, previous, d))
                {
                    break;
                }
            }

            previous = normal;
        }
    }

    /// <summary><paramref name="v"/> along a wall of unit normal <paramref name="n"/>: never longer than before.</summary>
    private static Vector2 Along(Vector2 v, Vector2 n)
    {
        v -= Vector2.Dot(v, n) * n;
        return v - (Vector2.Dot(v, n) * n); // again: what the first leaves is float residue of the longer vector, which can be large beside a short slide
    }

    /// <summary>
    /// Whether a slide stops: it points into the wall touched before (a concave corner), or back against
    /// the move <paramref name="d"/> (wedged between two walls, whose projections in turn send it back).
    /// </summary>
    private static bool Blocked(Vector2 slide, Vector2 previous, Vector2 d) =>
        Vector2.Dot(slide, previous) < -ConcaveTolerance * slide.Length()
        || Vector2.Dot(slide, d) < ConcaveTolerance * slide.Length() * d.Length();

    /// <summary>
    /// Earliest fraction <c>hit.T</c> (below the one given) of the move p → p + d of <paramref name="move"/>
    /// at which its disc, widened by <paramref name="widen"/> (a cylinder's radius, else 0), touches the
    /// segment a–b, and the unit normal from the segment to the centre there (<c>hit.Normal</c>). A disc
    /// already touching the segment beside its ends (within <see cref="PhysicsConstants.ContactTolerance"/>)
    /// and moving towards it is stopped at t = 0; one moving away or along it (within
    /// <see cref="ParallelTolerance"/>) is free. Else the segment is met where the move reaches its contact
    /// radius beside it (the offset lines: a centre that reaches that depth beyond an end, where it comes
    /// beside), or at an end, unless it only grazes that (closer than the graze, widened alike: see
    /// <see cref="SweepPoint"/>). A disc overlapping the segment by more than <c>hit.Depth</c> sets it to the
    /// overlap and <c>hit.Outward</c> to the normal there.
    /// </summary>
    public static void SweepSegment(in BodyMove move, Vector2 a, Vector2 b, float widen, ref WallHit hit)
    {
        Vector2 p = move.P, d = move.D;
        float radius = move.Radius + widen, graze = move.Graze + widen;
        Vector2 ab = b - a;
        float lengthSquared = ab.LengthSquared();
        float u0 = lengthSquared > 0f ? Math.Clamp(Vector2.Dot(p - a, ab) / lengthSquared, 0f, 1f) : 0f;
        Vector2 away = p - (a + (ab * u0));
        float distanceSquared = away.LengthSquared();
        bool beside = distanceSquared == 0f || (u0 > 0f && u0 < 1f);
        Vector2 n = distanceSquared == 0f ? OffsetNormal(ab, -d)
            : beside ? OffsetNormal(ab, away)      // beside the segment: its own normal, the same at every point (and as the offset lines' below)
            : away / MathF.Sqrt(distanceSquared);  // at an end: the circle's
        if (distanceSquared < radius * radius)
        {
            hit.Overlap(radius - MathF.Sqrt(distanceSquared), n);
        }

        float touch = radius + PhysicsConstants.ContactTolerance;
        if (beside && distanceSquared < touch * touch)
        {
            float into = Vector2.Dot(d, n);
            if (into < 0f && into * into > ParallelTolerance * ParallelTolerance * d.LengthSquared())
            {
                hit.Contact(0f, n);
            }

            return;
        }

        if (/* Stryker disable once Equality : a segment of no length has a NaN side, which approaches nothing */ lengthSquared > 0f)
        {
            Vector2 side = Vector2.Normalize(new Vector2(-ab.Y, ab.X));
            float s0 = Vector2.Dot(p - a, side);
            if (s0 < 0f)
            {
                (side, s0) = (-side, -s0);
            }

            float approach = -Vector2.Dot(d, side);
            if (approach > 0f)
            {
                // Met at the contact radius; a centre already nearer the line (beyond the segment's end) at
                // the sink's depth, or where it is. One that gets that near beyond an end and then comes
                // beside the segment having only grazed the end (see SweepPoint) is met where it comes beside.
                float line = s0 >= radius ? radius : MathF.Min(s0, graze + PhysicsConstants.ContactTolerance);
                float at = (s0 - line) / approach;
                float ua = Vector2.Dot(p - a, ab) / lengthSquared, du = Vector2.Dot(d, ab) / lengthSquared;
                float u = ua + (du * at);
                if ((u < 0f && du > 0f) || (u > 1f && du < 0f))
                {
                    float enter = u < 0f ? -ua / du : (1f - ua) / du;
                    (at, u) = s0 - (approach * enter) >= graze ? (enter, u < 0f ? 0f : 1f) : (1f, u);
                }

                if (u >= 0f && u <= 1f)
                {
                    hit.Contact(at, side);
                }
            }
        }

        SweepPoint(p, d, a, radius, graze, ref hit);
        SweepPoint(p, d, b, radius, graze, ref hit);
    }

    /// <summary>
    /// As <see cref="SweepSegment"/> for a single point (a segment's end): a ray against a circle. A move
    /// that comes no closer than <paramref name="graze"/> to the point only grazes it: a body sliding along
    /// a wall sits up to the sink the slide allows inside its contact radius (the float rounding), and
    /// taking the wall's end (or a collinear neighbour's) for a contact there turned the slide by the
    /// square root of that hair (3 mrad for 2e-6 m), so the body left the wall's line and met what the
    /// exact slide misses; if it goes on towards the wall, the offset line meets it where it comes beside.
    /// A body already sunk into the circle by no more than the sink meets it at the sink's depth; deeper,
    /// where it is, when moving more than <see cref="PhysicsConstants.ContactTolerance"/> deeper.
    /// </summary>
    private static void SweepPoint(Vector2 p, Vector2 d, Vector2 c, float radius, float graze, ref WallHit hit)
    {
        Vector2 m = p - c;
        float b = Vector2.Dot(m, d);
        if (b >= 0f)
        {
            return; // moving away from it
        }

        float a = d.LengthSquared();
        float mm = m.LengthSquared();
        float circle = radius, limit = graze;
        if (mm < radius * radius)
        {
            circle = MathF.Min(MathF.Sqrt(mm), graze + PhysicsConstants.ContactTolerance);
            limit = circle - PhysicsConstants.ContactTolerance;
        }

        float deepest = (m + (d * MathF.Min(-b / a, 1f))).LengthSquared(); // the closest the move comes, squared
        if (limit > 0f && deepest >= limit * limit)
        {
            return; // a graze
        }

        float cc = mm - (circle * circle);
        float discriminant = (b * b) - (a * cc);
        // Stryker disable once Statement,Block : the root of a negative discriminant is NaN, which is not kept
        if (discriminant < 0f)
        {
            return;
        }

        float t = MathF.Max((-b - MathF.Sqrt(discriminant)) / a, 0f);
        if (t <= hit.T)
        {
            Vector2 at = p + (d * t) - c;
            float length = at.Length();
            if (length > 0f)
            {
                hit.Contact(t, at / length);
            }
        }
    }

    /// <summary>The unit normal of a segment along <paramref name="ab"/> on the side <paramref name="towards"/> points to.</summary>
    private static Vector2 OffsetNormal(Vector2 ab, Vector2 towards)
    {
        Vector2 n = ab == Vector2.Zero ? towards : new Vector2(-ab.Y, ab.X);
        if (n == Vector2.Zero)
        {
            return Vector2.UnitX;
        }

        n = Vector2.Normalize(n);
        return Vector2.Dot(n, towards) < 0f ? -n : n;
    }
}
