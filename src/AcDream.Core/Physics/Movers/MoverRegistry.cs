using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>
/// The things that move: creatures, players, doors, registered at run time with an id, a shape, a position and an
/// orientation (world frame, metres), the cell they are in and their state. Every <c>Resolve</c> meets the movers of the
/// state last committed, point and body alike, across seams, indoors and outdoors (a mover is found by its position,
/// whatever cell it is in): a solid one is a wall, an Ethereal one is only touched (see <see cref="MoverState"/> for who
/// blocks whom).
/// </summary>
/// <remarks>
/// <para>
/// Changes (<see cref="Add"/>, <see cref="Move"/>, <see cref="SetState"/>, <see cref="Remove"/>, <see cref="Open"/>,
/// <see cref="Close"/>) are kept until <see cref="Commit"/> publishes them all at once: a call sees one whole committed
/// state from its start to its end, never part of an update. Changes are made from one thread at a time (they are
/// serialised); any number of threads resolve meanwhile and never wait for them. Moving a mover allocates nothing; a
/// commit allocates only when more movers are registered than ever before, when a reader still holds every spare state,
/// or when a registration slot takes a mover of another shape (after an <see cref="Add"/> or a <see cref="Remove"/>).
/// </para>
/// <para>With no movers committed, every answer is the engine's without them, bit for bit, and costs one null check.</para>
/// </remarks>
public sealed partial class MoverRegistry
{
    private readonly WorldFrame _frame;
    private readonly object _write = new();
    private readonly Dictionary<uint, int> _slots = [];
    private readonly List<MoverFrame> _spare = [];
    private Slot[] _movers = new Slot[16];
    private int[] _buckets = [];
    private int _count;
    private long _version;
    private MoverFrame? _current;

    /// <summary>The engine's recorder (<see cref="PhysicsEngine.Recorder"/>), told every change inside the lock; null: none.</summary>
    internal IEngineRecorder? Recorder;

    internal MoverRegistry(WorldFrame frame) => _frame = frame;

    /// <summary>How many movers are registered (committed or not).</summary>
    public int Count
    {
        get
        {
            lock (_write)
            {
                return _count;
            }
        }
    }

    /// <summary>
    /// Registers a mover (seen by <c>Resolve</c> from the next <see cref="Commit"/>).
    /// </summary>
    /// <param name="id">Its id, not 0 and not registered.</param>
    /// <param name="shape">Its walls in its own frame.</param>
    /// <param name="position">Its origin, world frame, metres (feet of a creature).</param>
    /// <param name="cellId">The cell it is in, a full <c>0xXXYYCCCC</c> id: its landblock is the frame its walls are placed in.</param>
    /// <param name="orientation">A turn about Z (creatures and doors stand upright); need not be unit.</param>
    /// <param name="state">What it is and its bits.</param>
    /// <exception cref="ArgumentException">An argument is invalid: the message names it, the id and what is wrong.</exception>
    public void Add(uint id, MoverShape shape, Vector3 position, uint cellId, Quaternion orientation, MoverState state)
    {
        ArgumentNullException.ThrowIfNull(shape);
        lock (_write)
        {
            if (id == 0 || _slots.ContainsKey(id))
            {
                throw new ArgumentException($"mover 0x{id:X8}: {(id == 0 ? "0 is not an id" : "already registered")}.", nameof(id));
            }

            Slot slot = Place(id, position, cellId, orientation);
            (slot.Id, slot.Shape, slot.State, slot.Version) = (id, shape, state, ++_version);
            if (_count == _movers.Length)
            {
                Array.Resize(ref _movers, 2 * _count);
            }

            _slots.Add(id, _count);
            _movers[_count++] = slot;
            Recorder?.MoverAdded(id, shape, position, cellId, orientation, state);
        }
    }

    /// <summary>Moves a registered mover (seen from the next <see cref="Commit"/>); arguments as for <see cref="Add"/>. Allocates nothing.</summary>
    /// <exception cref="ArgumentException">The id is not registered, or an argument is invalid.</exception>
    public void Move(uint id, Vector3 position, uint cellId, Quaternion orientation)
    {
        lock (_write)
        {
            ref Slot slot = ref Find(id);
            Slot placed = Place(id, position, cellId, orientation);
            (slot.X, slot.Y, slot.Local, slot.Cos, slot.Sin, slot.CellId, slot.Version) =
                (placed.X, placed.Y, placed.Local, placed.Cos, placed.Sin, placed.CellId, ++_version);
            Recorder?.MoverMoved(id, position, cellId, orientation);
        }
    }

    /// <summary>Sets a registered mover's state (seen from the next <see cref="Commit"/>); a door told to close by <see cref="Close"/> stops closing.</summary>
    /// <exception cref="ArgumentException">The id is not registered.</exception>
    public void SetState(uint id, MoverState state)
    {
        lock (_write)
        {
            ref Slot slot = ref Find(id);
            (slot.State, slot.Closing) = (state, false);
            Recorder?.MoverStateSet(id, state);
        }
    }

    /// <summary>The state of a registered mover as it will be committed.</summary>
    /// <exception cref="ArgumentException">The id is not registered.</exception>
    public MoverState GetState(uint id)
    {
        lock (_write)
        {
            return Find(id).State;
        }
    }

    /// <summary>Removes a mover (gone from the next <see cref="Commit"/>); false when it was not registered.</summary>
    public bool Remove(uint id)
    {
        lock (_write)
        {
            bool removed = _slots.Remove(id, out int i);
            if (removed)
            {
                RemoveAt(i);
            }

            Recorder?.MoverRemoved(id, removed);
            return removed;
        }
    }

    /// <summary>Removes every mover whose cell is in the landblock of <paramref name="landblockId"/> (<c>0xXXYY....</c>), as that landblock unloads; how many.</summary>
    public int RemoveLandblock(uint landblockId)
    {
        lock (_write)
        {
            int removed = 0;
            for (int i = _count - 1; i >= 0; i--)
            {
                if (CellIds.Prefix(_movers[i].CellId) == CellIds.Prefix(landblockId))
                {
                    _slots.Remove(_movers[i].Id);
                    RemoveAt(i);
                    removed++;
                }
            }

            Recorder?.MoversOfLandblockRemoved(landblockId, removed);
            return removed;
        }
    }

    /// <summary>Opens a door: Ethereal from the next <see cref="Commit"/> (the game's door opens at once).</summary>
    /// <exception cref="ArgumentException">The id is not a registered door.</exception>
    public void Open(uint doorId)
    {
        lock (_write)
        {
            ref Slot door = ref FindDoor(doorId);
            door.State = door.State with { Physics = door.State.Physics | PhysicsStateFlags.Ethereal };
            door.Closing = false;
            Recorder?.DoorOpened(doorId);
        }
    }

    /// <summary>
    /// Closes a door: solid at the first <see cref="Commit"/> at which no other mover's cylinder overlaps its walls or stands
    /// inside its slab; until then it stays Ethereal and is re-checked at every commit (the game's door hold: a door never
    /// closes on someone standing in it).
    /// </summary>
    /// <exception cref="ArgumentException">The id is not a registered door.</exception>
    public void Close(uint doorId)
    {
        lock (_write)
        {
            ref Slot door = ref FindDoor(doorId);
            door.Closing = (door.State.Physics & PhysicsStateFlags.Ethereal) != 0;
            Recorder?.DoorClosed(doorId);
        }
    }

    /// <summary>
    /// Publishes every change since the last commit as one whole state: calls that start after it see all of them,
    /// calls under way finish on the state they started with. Doors told to close become solid here once nothing
    /// overlaps them.
    /// </summary>
    public void Commit()
    {
        lock (_write)
        {
            if (_count == 0)
            {
                Committed(null);
                Interlocked.Exchange(ref _current, null);
                return;
            }

            MoverFrame next = Spare();
            Interlocked.Increment(ref next.Sequence); // odd: being written (a call reading it unheld sees the change)
            Fill(next);
            HoldDoors(next);
            Committed(next);
            Interlocked.Increment(ref next.Sequence);
            Interlocked.Exchange(ref _current, next); // (a full fence: the frame is written before it is seen)
        }
    }

    /// <summary>The committed state, held until <see cref="Release"/>: never rewritten while held. Null when no mover is committed.</summary>
    internal MoverFrame? Hold()
    {
        while (Volatile.Read(ref _current) is MoverFrame frame)
        {
            Interlocked.Increment(ref frame.Readers);
            if (ReferenceEquals(Volatile.Read(ref _current), frame))
            {
                return frame; // still current after the hold is counted: the writer will not pick it
            }

            Interlocked.Decrement(ref frame.Readers);
        }

        return null;
    }

    internal static void Release(MoverFrame? frame)
    {
        if (frame is not null)
        {
            Interlocked.Decrement(ref frame.Readers);
        }
    }

    /// <summary>Whether any mover is committed (one read; a call that finds none reads nothing else of the movers).</summary>
    internal bool Any => Volatile.Read(ref _current) is not null;

    /// <summary>
    /// Whether the committed state has no mover whose walls reach into the box (the frame of landblock x, y), read without
    /// holding it: true only when the state read was whole (its sequence even and unchanged across the read).
    /// <paramref name="occupied"/>: the state read, when it was whole and has one near; null when it was not whole
    /// (look again, holding it).
    /// </summary>
    internal bool NoneNear(int x, int y, Vector2 lo, Vector2 hi, out MoverFrame? occupied)
    {
        occupied = null;
        if (Volatile.Read(ref _current) is not MoverFrame frame)
        {
            return true;
        }

        int sequence = Volatile.Read(ref frame.Sequence);
        bool near = frame.Occupied(x, y, lo, hi);
        Volatile.ReadBarrier(); // the reads above complete before the sequence is read again
        bool whole = (sequence & 1) == 0 && Volatile.Read(ref frame.Sequence) == sequence && ReferenceEquals(Volatile.Read(ref _current), frame);
        occupied = whole && near ? frame : null;
        return whole && !near;
    }
}
