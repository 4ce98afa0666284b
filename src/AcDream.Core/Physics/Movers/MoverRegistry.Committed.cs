namespace AcDream.Core.Physics;

/// <summary>What the last commit published: its number, and each door's state as moves meet it.</summary>
public sealed partial class MoverRegistry
{
    private long _commitNumber;

    /// <summary>
    /// How many times <see cref="Commit"/> has run: the number of the committed state calls read now (0 before the first
    /// commit). A move's answer names the number of the state it read (<see cref="MoveResult.Commit"/>), so a client can
    /// tell which movers' positions an answer saw.
    /// </summary>
    public long CommitNumber => Volatile.Read(ref _commitNumber);

    /// <summary>
    /// Where a door is in the state last committed, as moves and casts meet it: <see cref="DoorState.Closing"/> from the
    /// first commit after <see cref="Close"/> to the commit that makes it solid. The changes made since are
    /// <see cref="GetPendingDoorState"/>'s.
    /// </summary>
    /// <exception cref="ArgumentException">The id is not a registered door, or the door has not been committed yet.</exception>
    public DoorState GetDoorState(uint doorId)
    {
        lock (_write)
        {
            ref Slot door = ref FindDoor(doorId);
            return door.Committed ?? throw new ArgumentException(
                $"door 0x{doorId:X8} is registered but not yet committed: no move has met it (its pending state is GetPendingDoorState's).", nameof(doorId));
        }
    }

    /// <summary>
    /// Where a door will be at the next <see cref="Commit"/>, with the changes made since the last one (moves meet the
    /// state last committed, <see cref="GetDoorState"/>): <see cref="DoorState.Closing"/> from <see cref="Close"/> to the
    /// commit that makes it solid.
    /// </summary>
    /// <exception cref="ArgumentException">The id is not a registered door.</exception>
    public DoorState GetPendingDoorState(uint doorId)
    {
        lock (_write)
        {
            return Pending(in FindDoor(doorId));
        }
    }

    private static DoorState Pending(in Slot door) =>
        door.Closing ? DoorState.Closing : (door.State.Physics & PhysicsStateFlags.Ethereal) != 0 ? DoorState.Open : DoorState.Closed;

    /// <summary>Numbers the commit under way and records each door's state in it (<paramref name="next"/> null: a commit with no mover).</summary>
    private void Committed(MoverFrame? next)
    {
        long number = _commitNumber + 1;
        if (next is not null)
        {
            next.Commit = number;
            for (int i = 0; i < _count; i++)
            {
                ref Slot slot = ref _movers[i];
                slot.Committed = slot.State.Kind == MoverKind.Door ? Pending(in slot) : null;
            }
        }

        Volatile.Write(ref _commitNumber, number);
        Recorder?.Committed(number);
    }
}
