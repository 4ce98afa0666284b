using System.Numerics;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.Movers;

namespace AcDream.Core.Physics.Body;

/// <summary>The movers a call's move touched, blocking or not, for the caller that asks (a pass after the move).</summary>
internal static class Touches
{
    /// <summary>Most touches one call writes in the order touched (their fractions on the stack, 4 bytes each): 64; more are written after them in the order the committed state files them, where the span has room.</summary>
    public const int MaxWritten = 64;

    /// <summary>
    /// Writes into <paramref name="touched"/> the ids of the movers met (not the mover itself, not one both Ethereal and
    /// IgnoreCollisions) whose walls the disc of the body (or a point) grown by <see cref="PhysicsConstants.TouchReach"/>
    /// meets on the straight line from the request's start to the answer, over the height from the lower feet to the
    /// higher head (a point: to its step up), and <paramref name="stoppedBy"/> (a point's sub-step refused before the
    /// mover it would cross stops short of it); how many there are. They are written in the order the line first touches
    /// them (one it overlaps at its start first, the one that stopped it short last; equal fractions in the order the
    /// committed state files them), the first that fit: the first <see cref="MaxWritten"/> in that order, any after them in the order the state files them.
    /// </summary>
    public static int Along(WorldFrame frame, ref Neighbourhood lands, in MoveRequest request, in ResolveResult result, uint stoppedBy, Span<uint> touched)
    {
        (Vector3 start, uint cellId, float stepUp, MoverBody? body) = (request.Position, request.CellId, request.StepUpHeight, request.Options.Body);
        MoverFrame movers = lands.Movers!;
        frame.Locate(start, cellId, out int x, out int y, out Vector2 p0);
        Vector2 p1 = new Vector2(result.Position.X, result.Position.Y) - frame.Origin(x, y);
        float radius = (body?.Radius ?? 0f) + PhysicsConstants.TouchReach;
        float zLow = MathF.Min(start.Z, result.Position.Z);
        float zHigh = MathF.Max(start.Z, result.Position.Z) + MathF.Max(body?.Height ?? stepUp, PhysicsConstants.TouchReach);
        var move = new BodyMove(p0, p1 - p0, radius, radius, 0f, zLow, zHigh);
        Vector2 lo = Vector2.Min(p0, p1) - new Vector2(radius), hi = Vector2.Max(p0, p1) + new Vector2(radius);
        Span<float> fractions = stackalloc float[Math.Min(touched.Length, MaxWritten)];
        int count = 0;
        for (Neighbourhood.MoverCursor near = lands.MoversNear(x, y, new WallBox(lo, hi, zLow, zHigh)); near.MoveNext();)
        {
            int j = near.Current;
            var hit = WallHit.None;
            MoverSolid.Sweep(movers.Walls[j], near.Offset, lo - near.Offset, hi - near.Offset, in move, ref hit);
            if (hit.T < 1f || hit.Depth > 0f)
            {
                stoppedBy = movers.Ids[j] == stoppedBy ? 0 : stoppedBy; // named here
                Put(touched, fractions, count++, movers.Ids[j], hit.Depth > 0f ? 0f : hit.T);
            }
        }

        if (stoppedBy != 0)
        {
            Put(touched, fractions, count++, stoppedBy, 1f);
        }

        return count;
    }

    /// <summary>
    /// Puts <paramref name="id"/>, first touched at fraction <paramref name="t"/>, among the <paramref name="counted"/> touches
    /// so far: the first <paramref name="fractions"/>.Length of them in order (after every one touched no later), and what
    /// falls out of that ordered part when it is full written after it, in the order met, where <paramref name="ids"/> has room.
    /// </summary>
    private static void Put(Span<uint> ids, Span<float> fractions, int counted, uint id, float t)
    {
        int written = Math.Min(counted, fractions.Length);
        int at = written;
        while (at > 0 && fractions[at - 1] > t)
        {
            at--;
        }

        if (written == fractions.Length)
        {
            uint spilled = at == written ? id : ids[written - 1];
            if (counted < ids.Length)
            {
                ids[counted] = spilled;
            }

            if (at == written)
            {
                return;
            }

            written--; // (its last was spilled)
        }

        for (int k = written; k > at; k--)
        {
            (ids[k], fractions[k]) = (ids[k - 1], fractions[k - 1]);
        }

        (ids[at], fractions[at]) = (id, t);
    }
}
