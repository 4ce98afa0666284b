using System.Numerics;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.Movers;

namespace AcDream.Core.Physics;

// MoverRegistry, a commit's work: a spare frame filled with the movers, filed by square, and the doors it holds.
public sealed partial class MoverRegistry
{
    private MoverFrame Spare()
    {
        MoverFrame? current = _current;
        foreach (MoverFrame frame in _spare)
        {
            if (!ReferenceEquals(frame, current) && Volatile.Read(ref frame.Readers) == 0)
            {
                return frame;
            }
        }

        var added = new MoverFrame(); // every spare state is held or current: one more (rare)
        _spare.Add(added);
        return added;
    }

    private void Fill(MoverFrame f)
    {
        int n = _count;
        if (f.Ids.Length < n)
        {
            int size = Math.Max(n, _movers.Length);
            f.Ids = new uint[size];
            f.States = new MoverState[size];
            f.LandblockX = new int[size];
            f.LandblockY = new int[size];
            f.SquareX = new int[size];
            f.SquareY = new int[size];
            f.Order = new int[size];
            Array.Resize(ref f.Walls, size);
            Array.Resize(ref f.Shapes, size);
            Array.Resize(ref f.Versions, size);
        }

        float reach = 0f;
        for (int i = 0; i < n; i++)
        {
            ref readonly Slot m = ref _movers[i];
            (f.Ids[i], f.States[i], f.LandblockX[i], f.LandblockY[i]) = (m.Id, m.State, m.X, m.Y);
            reach = MathF.Max(reach, m.Shape.Reach);
            if (f.Versions[i] == m.Version && ReferenceEquals(f.Shapes[i], m.Shape))
            {
                continue; // placed when this state was last written, and not moved since
            }

            if (!ReferenceEquals(f.Shapes[i], m.Shape))
            {
                (f.Walls[i], f.Shapes[i]) = (m.Shape.Walls.Copy(), m.Shape);
            }

            f.Walls[i].PlaceFrom(m.Shape.Walls, m.Cos, m.Sin, m.Local);
            f.Versions[i] = m.Version;
        }

        (f.Count, f.Reach) = (n, reach);
        File(f);
    }

    /// <summary>Files the movers by the square of their origins: a counting sort into the buckets of the squares' hash.</summary>
    private void File(MoverFrame f)
    {
        int n = f.Count, size = 64;
        while (size < 2 * n)
        {
            size *= 2;
        }

        if (f.Heads.Length < size + 1)
        {
            (f.Heads, f.ById) = (new int[size + 1], new int[size]); // grown only: fewer movers keep the larger tables
        }

        size = f.Heads.Length - 1;
        (f.Mask, int[] heads) = (size - 1, f.Heads);
        Array.Clear(heads);
        if (_buckets.Length < n)
        {
            _buckets = new int[_movers.Length];
        }

        int[] buckets = _buckets;
        for (int i = 0; i < n; i++)
        {
            ref readonly Slot m = ref _movers[i];
            (f.SquareX[i], f.SquareY[i]) = (MoverFrame.Square(m.X, m.Local.X), MoverFrame.Square(m.Y, m.Local.Y));
            buckets[i] = f.Bucket(f.SquareX[i], f.SquareY[i]);
            heads[buckets[i]]++;
        }

        for (int b = 1; b <= size; b++)
        {
            heads[b] += heads[b - 1]; // each bucket's end
        }

        for (int i = n - 1; i >= 0; i--)
        {
            f.Order[--heads[buckets[i]]] = i; // from the back: each bucket's end becomes its start, in the movers' order
        }

        f.FileCells(size);
        Occupy(f, 4 * size); // (each mover reaches into at most four landblocks)
        Array.Clear(f.ById);
        for (int i = 0; i < n; i++)
        {
            int at = f.IdSlot(f.Ids[i]);
            while (f.ById[at] != 0)
            {
                at = (at + 1) & f.Mask;
            }

            f.ById[at] = i + 1;
        }
    }

    /// <summary>Marks in each landblock's bits the outdoor cells every mover's walls reach into (its own and its neighbours').</summary>
    private static void Occupy(MoverFrame f, int size)
    {
        if (f.Landblocks.Length < size)
        {
            (f.Landblocks, f.Occupancy) = (new int[size], new ulong[size]); // grown only
        }

        size = f.Landblocks.Length;

        Array.Clear(f.Landblocks);
        const float side = PhysicsConstants.LandblockSize;
        for (int i = 0; i < f.Count; i++)
        {
            CellWalls w = f.Walls[i];
            for (int dx = w.Min.X < 0f ? -1 : 0; dx <= (w.Max.X > side ? 1 : 0); dx++)
            {
                for (int dy = w.Min.Y < 0f ? -1 : 0; dy <= (w.Max.Y > side ? 1 : 0); dy++)
                {
                    int x = f.LandblockX[i] + dx, y = f.LandblockY[i] + dy;
                    if (!CellIds.IsInWorld(x, y))
                    {
                        continue;
                    }

                    var offset = new Vector2(dx * side, dy * side);
                    int key = CellIds.LandblockIndex(x, y) + 1, at = MoverFrame.LandblockSlot(key, size);
                    while (f.Landblocks[at] != 0 && f.Landblocks[at] != key)
                    {
                        at = (at + 1) & (size - 1);
                    }

                    f.Occupancy[at] = (f.Landblocks[at] == 0 ? 0 : f.Occupancy[at]) | MoverFrame.Cells(w.Min - offset, w.Max - offset);
                    f.Landblocks[at] = key;
                }
            }
        }
    }

    /// <summary>Doors told to close become solid once no other mover's cylinder overlaps their walls or stands inside them (<see cref="StandsInDoor"/>) in the state about to be published.</summary>
    private void HoldDoors(MoverFrame f)
    {
        for (int i = 0; i < f.Count; i++)
        {
            ref Slot door = ref _movers[i];
            if (!door.Closing || Overlapped(f, i, _standsIn))
            {
                continue;
            }

            door.State = door.State with { Physics = door.State.Physics & ~PhysicsStateFlags.Ethereal };
            (door.Closing, f.States[i]) = (false, door.State);
        }
    }

    private static bool Overlapped(MoverFrame f, int door, StandsInDoor standsIn)
    {
        CellWalls walls = f.Walls[door];
        int x = f.LandblockX[door], y = f.LandblockY[door];
        for (MoverFrame.Near near = f.Around(x, y, walls.Min, walls.Max); near.MoveNext();)
        {
            int j = near.Current;
            if (j == door || f.States[j].Kind == MoverKind.Door || !MoverState.Meets(in f.States[j]) || !f.TryOffset(j, x, y, out Vector2 offset, out _))
            {
                continue;
            }

            foreach (WallPolygon c in f.Walls[j].Polygons)
            {
                if (c.Radius > 0f && standsIn(walls, in c, offset))
                {
                    return true;
                }
            }
        }

        return false;
    }
}
