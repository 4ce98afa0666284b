using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.Movers;

namespace AcDream.Core.Physics.World;

/// <summary>The movers of a call whose queries lie along a long path (a cast): each query asks the squares near it.</summary>
internal partial struct Neighbourhood
{
    /// <summary>
    /// Holds the committed movers for a call as <see cref="Meet"/> does, but lists none: each query of the call
    /// (<see cref="MoversAlong"/>) asks the squares its own box covers, so a call whose path is long pays for the movers
    /// near its path, not for those of the box about its start that its reach spans.
    /// </summary>
    /// <returns>Whether the call holds movers (and must <see cref="Release"/> them).</returns>
    [MethodImpl(MethodImplOptions.NoInlining)] // out of the common path: only with movers committed
    public bool MeetAlong(MoverRegistry movers, in WorldFrame frame, Vector3 start, uint cellId, float reach, uint self) =>
        HoldMovers(movers, in frame, start, cellId, reach, self);

    /// <summary>
    /// Holds the committed movers when some mover's walls reach into the box within <paramref name="reach"/> of
    /// <paramref name="start"/> (seen from above), and sets this thread's record of the call (listing none); false, holding
    /// none, when no mover is near in the state committed at the call's start.
    /// </summary>
    private bool HoldMovers(MoverRegistry movers, in WorldFrame frame, Vector3 start, uint cellId, float reach, uint self)
    {
        frame.Locate(start, cellId, out int x, out int y, out Vector2 local);
        Vector2 lo = local - new Vector2(reach), hi = local + new Vector2(reach);
        if (movers.NoneNear(x, y, lo, hi, out MoverFrame? occupied) || movers.Hold() is not MoverFrame held)
        {
            return false; // no mover near in the state committed at the call's start: the call reads none
        }

        if (held != occupied && !held.Occupied(x, y, lo, hi))
        {
            Physics.MoverRegistry.Release(held); // (a later state than the one looked at unheld, with none near)
            return false;
        }

        MoverCall call = MoverCall.OfThisThread();
        call.Set(held, x, y, lo, hi, self);
        _call = call;
        return true;
    }

    /// <summary>
    /// The movers held by <see cref="MeetAlong"/> (not itself, met, in a landblock next to the start's or the start's)
    /// whose walls meet <paramref name="box"/> (the frame of landblock x, y), each once: of those filed in the squares the box
    /// covers, grown by the furthest reach of any mover's walls, found by the cells with a mover filed
    /// (<see cref="MoverFrame.FiledIn"/>); none when no mover's walls reach into the outdoor cells it covers.
    /// </summary>
    public readonly AlongCursor MoversAlong(int x, int y, WallBox box) => new(_call!, x, y, box);

    /// <summary>The movers of <see cref="MoversAlong"/>: each with its walls' offset from the query's frame.</summary>
    internal ref struct AlongCursor
    {
        private readonly MoverCall _call;
        private readonly WallBox _box;
        private readonly int _x, _y;
        private MoverFrame.Filed _grid;
        private readonly bool _any;

        public AlongCursor(MoverCall call, int x, int y, WallBox box)
        {
            (_call, _x, _y, _box) = (call, x, y, box);
            MoverFrame frame = call.Frame!;
            _any = frame.Occupied(x, y, box.Lo, box.Hi);
            _grid = _any ? frame.FiledIn(x, y, box.Lo, box.Hi) : default;
        }

        public int Current { get; private set; }

        public Vector2 Offset { get; private set; }

        public bool MoveNext()
        {
            if (!_any)
            {
                return false;
            }

            MoverCall call = _call;
            MoverFrame movers = call.Frame!;
            while (_grid.MoveNext())
            {
                int j = _grid.Current;
                call.Examined++;
                CellWalls w = movers.Walls[j];
                if (movers.Ids[j] != call.SelfId && MoverState.Meets(in movers.States[j]) && movers.TryOffset(j, call.X, call.Y, out _, out _)
                    && movers.TryOffset(j, _x, _y, out Vector2 offset, out _) && new WallBounds(w.Min, w.Max, w.ZMin, w.ZMax).Meets(in _box, offset))
                {
                    (Current, Offset) = (j, offset);
                    return true;
                }
            }

            return false;
        }
    }
}
