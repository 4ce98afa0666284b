namespace AcDream.Core.Physics;

/// <summary>
/// A mover's state: what it is and the game's bits the rules read. The rules, for a moving object M and a registered
/// target T (<see cref="Blocks"/>, <see cref="Meets"/>): T both Ethereal and IgnoreCollisions is skipped; an Ethereal T
/// does not block but is touched; two players pass through each other (touched) unless one is impenetrable, or both
/// are player-killers, or both are PK-lite; an M that ignores creatures passes creatures and players (touched).
/// </summary>
/// <param name="Kind">What it is.</param>
/// <param name="Physics">The game's physics-state bits (<see cref="PhysicsStateFlags"/>).</param>
/// <param name="Description">The game's object-description bits of a player (<see cref="ObjectDescriptionFlags"/>).</param>
/// <param name="IgnoresCreatures">Moving, it passes creatures and players (and records them as touched).</param>
public readonly record struct MoverState(
    MoverKind Kind,
    PhysicsStateFlags Physics = PhysicsStateFlags.None,
    ObjectDescriptionFlags Description = ObjectDescriptionFlags.None,
    bool IgnoresCreatures = false)
{
    /// <summary>A solid creature.</summary>
    public static MoverState Creature => new(MoverKind.Creature);

    /// <summary>A solid player (not a player-killer).</summary>
    public static MoverState Player => new(MoverKind.Creature, Description: ObjectDescriptionFlags.Player);

    /// <summary>A closed door.</summary>
    public static MoverState Door => new(MoverKind.Door);

    /// <summary>The state of a moving object that is not registered: an object that is not a creature.</summary>
    internal static MoverState Unregistered => new(MoverKind.Object);

    private bool IsPlayer => (Description & ObjectDescriptionFlags.Player) != 0;

    /// <summary>A creature or a player: what a cast that ignores creatures passes.</summary>
    internal bool IsCreature => Kind == MoverKind.Creature || IsPlayer;

    /// <summary>Whether <paramref name="target"/> is met at all by a move of this one: not both Ethereal and IgnoreCollisions.</summary>
    public static bool Meets(in MoverState target) =>
        (target.Physics & (PhysicsStateFlags.Ethereal | PhysicsStateFlags.IgnoreCollisions))
        != (PhysicsStateFlags.Ethereal | PhysicsStateFlags.IgnoreCollisions);

    /// <summary>Whether <paramref name="target"/> stops a move of <paramref name="mover"/> (the rules above); one that is met and does not block is only touched.</summary>
    public static bool Blocks(in MoverState mover, in MoverState target)
    {
        if ((target.Physics & PhysicsStateFlags.Ethereal) != 0)
        {
            return false;
        }

        if (mover.IgnoresCreatures && target.IsCreature)
        {
            return false;
        }

        if (mover.IsPlayer && target.IsPlayer)
        {
            ObjectDescriptionFlags both = mover.Description & target.Description;
            return ((mover.Description | target.Description) & ObjectDescriptionFlags.Impenetrable) != 0
                || (both & (ObjectDescriptionFlags.PlayerKiller | ObjectDescriptionFlags.PkLite)) != 0;
        }

        return true;
    }
}
