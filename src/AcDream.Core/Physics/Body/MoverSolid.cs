using System.Numerics;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.Movers;

namespace AcDream.Core.Physics.Body;

/// <summary>
/// A mover's walls as a solid: its upright plane walls that meet a body's band, seen from above, are the outline of
/// the solid when they close (each wall a segment A → B with the outside on its right, as <see cref="CellWalls"/> orders
/// them from the polygon's outward normal; closed when the segments add up to nothing, as a loop does). A body whose
/// centre is inside that outline (the walls wind round it once with their outside on the right: its winding number is positive; walls facing in, as a pen's, wind the other way and make no solid) is as deep in the solid as its contact
/// radius plus the centre's distance to the nearest of those walls, and every side of the solid is behind it: there the
/// sweep meets the solid only by the depth rule (<see cref="Sweep"/>), not by its walls. Anywhere else, and for a
/// mover's cylinders, its walls are swept as any object's. Landblock-local metres; allocation-free.
/// </summary>
internal static class MoverSolid
{
    /// <summary>Segments adding up to no more than this (metres, seen from above) close: what float rounding leaves of a loop of placed walls.</summary>
    private const float Closure = 1e-3f;

    /// <summary>
    /// A move from inside (or deep against the walls) that leaves the nearest side by less than this share of the sink is
    /// met at its start and lifted out by the sink: more than the rounding of an answer to the world frame (at most 0.71
    /// of a float spacing; the sink is at least one), and a move already lifted is not met again.
    /// </summary>
    private const float Leaving = 0.75f;

    /// <summary>
    /// Whether a mover's cylinder (<paramref name="cylinder"/>, its frame <paramref name="offset"/> from the door's) held
    /// still overlaps the door's walls or stands inside them (<see cref="Sweep"/> of a disc of its radius that does not move):
    /// the registry's <see cref="StandsInDoor"/>, asked of a closing door at a commit.
    /// </summary>
    public static bool StandsIn(CellWalls door, in WallPolygon cylinder, Vector2 offset)
    {
        var still = new BodyMove(cylinder.A + offset, Vector2.Zero, cylinder.Radius, cylinder.Radius, 0f, cylinder.ZMin, cylinder.ZMax);
        var hit = WallHit.None;
        Sweep(door, Vector2.Zero, still.P - new Vector2(cylinder.Radius), still.P + new Vector2(cylinder.Radius), in still, ref hit); // (its faces, or wholly inside the slab)
        return hit.Depth > 0f;
    }

    /// <summary>
    /// Sweeps <paramref name="move"/> against one mover's walls (their landblock frame <paramref name="offset"/> from the
    /// move's; the sweep's box <paramref name="lo"/>–<paramref name="hi"/> in their frame). A move whose start is inside the
    /// mover's solid overlaps it by its depth (out along the nearest wall's outward normal), and meets it at its start
    /// unless it leaves that wall by <see cref="Leaving"/> of the sink: it may leave through any side, and else slides along
    /// the nearest (which keeps its depth) and out by the sink; the mover's cylinders are swept as ever. Else the walls as
    /// any object's (<see cref="BodySweep.SweepWalls(CellWalls, Vector2, Vector2, Vector2, in BodyMove, ref WallHit)"/>),
    /// and an overlap of them deeper than four sinks (beyond the slide's push back) is met at the start the same way.
    /// </summary>
    public static void Sweep(CellWalls walls, Vector2 offset, Vector2 lo, Vector2 hi, in BodyMove move, ref WallHit hit)
    {
        if (!Inside(walls, move.P - offset, move.ZLow, move.ZHigh, out float distance, out Vector2 outward))
        {
            // Outside it: its walls as any object's, and the lift out of one it overlaps deeper than the slide's push back reaches.
            var own = new WallHit { T = 1f, Current = hit.Current };
            BodySweep.SweepWalls(walls, offset, lo, hi, in move, ref own);
            hit.Contact(own.T, own.Normal);
            Lift(ref hit, in move, own.Depth, own.Outward, own.Depth >= 4f * move.Sink);
            return;
        }

        Lift(ref hit, in move, move.Radius + distance, outward, lifts: true);

        foreach (ref readonly WallPolygon w in walls.Polygons.AsSpan())
        {
            if (w.Radius > 0f && w.ZMax > move.ZLow && w.ZMin < move.ZHigh && Boxes.Overlaps(w.Min, w.Max, lo, hi))
            {
                BodySweep.SweepSegment(in move, w.A + offset, w.B + offset, w.Radius, ref hit);
            }
        }
    }

    /// <summary>
    /// The overlap of <paramref name="depth"/> out along <paramref name="outward"/>; where it <paramref name="lifts"/> and the
    /// move does not leave it by <see cref="Leaving"/> of the sink, a contact at the start with that normal too, past which
    /// the slide goes on along it and out by the sink (<see cref="WallHit.Lift"/>, swept with the rest of the move).
    /// </summary>
    private static void Lift(ref WallHit hit, in BodyMove move, float depth, Vector2 outward, bool lifts)
    {
        lifts &= Vector2.Dot(move.D, outward) < Leaving * move.Sink;
        hit.Overlap(depth, outward, lifts ? outward * move.Sink : default);
        if (lifts)
        {
            hit.Contact(0f, outward);
        }
    }

    /// <summary>
    /// Whether <paramref name="p"/> (the walls' frame) is inside the outline the upright plane walls meeting the band
    /// <paramref name="zLow"/>–<paramref name="zHigh"/> close; then the distance from it to the nearest of them and that
    /// wall's outward unit normal.
    /// </summary>
    private static bool Inside(CellWalls walls, Vector2 p, float zLow, float zHigh, out float distance, out Vector2 outward)
    {
        distance = float.MaxValue;
        outward = default;
        if (p.X < walls.Min.X || p.X > walls.Max.X || p.Y < walls.Min.Y || p.Y > walls.Max.Y || walls.ZMax <= zLow || walls.ZMin >= zHigh)
        {
            return false;
        }

        Vector2 sum = default;
        int winding = 0;
        foreach (ref readonly WallPolygon w in walls.Polygons.AsSpan())
        {
            if (!w.IsUpright || w.Radius > 0f || w.ZMax <= zLow || w.ZMin >= zHigh)
            {
                continue;
            }

            Vector2 a = w.A, ab = w.B - w.A;
            float lengthSquared = ab.LengthSquared();
            if (lengthSquared == 0f)
            {
                continue;
            }

            sum += ab;
            float side = (ab.X * (p.Y - a.Y)) - (ab.Y * (p.X - a.X)); // > 0: p left of A → B
            if (a.Y <= p.Y && w.B.Y > p.Y && side > 0f)
            {
                winding++; // crossing the ray from p towards +X upward, p on its left
            }
            else if (w.B.Y <= p.Y && a.Y > p.Y && side < 0f)
            {
                winding--;
            }

            float u = Math.Clamp(Vector2.Dot(p - a, ab) / lengthSquared, 0f, 1f);
            float d = Vector2.Distance(p, a + (ab * u));
            if (d < distance)
            {
                distance = d;
                outward = Vector2.Normalize(new Vector2(ab.Y, -ab.X));
            }
        }

        return winding > 0 && sum.LengthSquared() <= Closure * Closure;
    }
}
