using System.Numerics;
using AcDream.Core.Physics.Surfaces;

namespace AcDream.Core.Physics;

// MoverRegistry, its slots: a registered mover's place, found by id, and removed.
public sealed partial class MoverRegistry
{
    private Slot Place(uint id, Vector3 position, uint cellId, Quaternion orientation)
    {
        if (!Geometry.IsFinite(position))
        {
            throw new ArgumentException($"mover 0x{id:X8}: position {position} must be finite.", nameof(position));
        }

        if (!CellIds.IsCellOfTheWorld(cellId))
        {
            throw new ArgumentException($"mover 0x{id:X8}: cellId 0x{cellId:X8} is not a cell of the world (outdoor 0x0001..0x0040, indoor 0x0100..0xFFFD).", nameof(cellId));
        }

        double w = orientation.W, z = orientation.Z, length = Math.Sqrt((w * w) + (z * z) + ((double)orientation.X * orientation.X) + ((double)orientation.Y * orientation.Y));
        if (!(length > 1e-6) || !double.IsFinite(length) || Math.Abs(orientation.X) > 1e-3 * length || Math.Abs(orientation.Y) > 1e-3 * length)
        {
            throw new ArgumentException(
                $"mover 0x{id:X8}: orientation {orientation} is not a turn about Z (finite, longer than 1e-6, X and Y within 1e-3 of its length).", nameof(orientation));
        }

        _frame.Locate(position, cellId, out int x, out int y, out Vector2 local);
        double turn = (w * w) + (z * z);
        return new Slot
        {
            X = x, Y = y, Local = new Vector3(local, position.Z), CellId = cellId,
            Cos = ((w * w) - (z * z)) / turn, Sin = 2.0 * w * z / turn,
        };
    }

    private ref Slot Find(uint id)
    {
        if (!_slots.TryGetValue(id, out int i))
        {
            throw new ArgumentException($"mover 0x{id:X8} is not registered.", nameof(id));
        }

        return ref _movers[i];
    }

    private ref Slot FindDoor(uint doorId)
    {
        if (!_slots.TryGetValue(doorId, out int i) || _movers[i].State.Kind != MoverKind.Door)
        {
            throw new ArgumentException($"mover 0x{doorId:X8} is not a registered door.", nameof(doorId));
        }

        return ref _movers[i];
    }

    private void RemoveAt(int i)
    {
        int last = --_count;
        if (i != last)
        {
            _movers[i] = _movers[last];
            _movers[i].Version = ++_version; // another mover in this slot: placed again
            _slots[_movers[i].Id] = i;
        }

        _movers[last] = default;
    }

    private struct Slot
    {
        public uint Id;
        public MoverShape Shape;
        public MoverState State;
        public bool Closing;
        public DoorState? Committed; // a door's state in the last commit; null before its first
        public int X, Y;
        public Vector3 Local;
        public double Cos, Sin;
        public uint CellId;
        public long Version;
    }
}
