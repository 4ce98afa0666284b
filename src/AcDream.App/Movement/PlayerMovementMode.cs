using System.Numerics;
using AcDream.Core.Physics;

namespace AcDream.App.Movement;

/// <summary>
/// The Phase B.2 seam: each frame turns the player's intent (<see cref="MovementIntent"/>) into a heading and a wanted
/// horizontal velocity, and moves a <see cref="Core.Physics.Character"/> with it (gravity, falls, jumps, steps and what
/// they met are the character's). Heading is a compass angle in radians: 0 faces north (+Y), π/2 east (+X).
/// </summary>
public sealed class PlayerMovementMode
{
    /// <summary>Walking speed: 2 m/s (a placeholder until B.2 reads the player's setup).</summary>
    public const float WalkSpeed = 2f;

    /// <summary>Running speed: 4 m/s (a placeholder until B.2 reads the player's setup).</summary>
    public const float RunSpeed = 4f;

    /// <summary>Turning speed: π/2 rad/s (90° per second).</summary>
    public const float TurnRate = MathF.PI / 2f;

    /// <summary>Highest rise one step may climb: 0.6 m (<see cref="CharacterSettings.StepUpHeight"/>).</summary>
    public const float StepUpHeight = 0.6f;

    /// <summary>Jump skill by default: 100, which jumps 1.64 m at full power.</summary>
    public const int DefaultJumpSkill = 100;

    /// <summary>Most movers one frame records as touched (<see cref="Touched"/>): 16.</summary>
    public const int MaxTouched = 16;

    private readonly PhysicsEngine _engine;
    private readonly uint[] _touched = new uint[MaxTouched];
    private int _touchedCount;

    /// <summary>Places the player, on the ground, not moving vertically.</summary>
    /// <param name="engine">The engine to move through.</param>
    /// <param name="position">Feet position, world metres.</param>
    /// <param name="cellId">The cell at <paramref name="position"/> (<c>0xXXYYCCCC</c>; outdoors any outdoor number).</param>
    /// <param name="heading">Compass heading, radians (0 north, π/2 east).</param>
    /// <param name="effects">The engine's effects (default: none, the spec's engine with a point; <see cref="MovementOptions.Player"/> for a player's body).</param>
    /// <exception cref="ArgumentException">The position or heading is not finite.</exception>
    public PlayerMovementMode(PhysicsEngine engine, Vector3 position, uint cellId, float heading, MovementOptions effects = default)
    {
        _engine = engine ?? throw new ArgumentNullException(nameof(engine));
        Character = new Character(engine, new CharacterSettings { Options = effects, StepUpHeight = StepUpHeight }, position, cellId);
        Heading = heading;
    }

    /// <summary>The character it moves.</summary>
    public Character Character { get; private set; }

    /// <summary>The engine's opt-in effects the player uses.</summary>
    public MovementOptions Effects => Character.Settings.Options;

    /// <summary>The player's mover id in the engine's <see cref="PhysicsEngine.Movers"/> (0: not registered): its own walls are not met, and each frame records the movers touched.</summary>
    public uint MoverId
    {
        get => Character.Settings.MoverId;
        init
        {
            Character old = Character;
            Character = new Character(_engine, old.Settings with { MoverId = value }, old.Position, old.CellId) { JumpSkill = old.JumpSkill, JumpPower = old.JumpPower };
        }
    }

    /// <summary>The ids of the movers the last <see cref="Update"/> touched, each once, in the order met, at most <see cref="MaxTouched"/>; empty without a <see cref="MoverId"/>.</summary>
    public ReadOnlySpan<uint> Touched => _touched.AsSpan(0, _touchedCount);

    /// <summary>The speed of a run, m/s: <see cref="RunSpeed"/> by default, above 0 and at most 50.</summary>
    /// <exception cref="ArgumentOutOfRangeException">On set: not finite, not above 0, or above 50 m/s.</exception>
    public float RunMetresPerSecond
    {
        get;
        init => field = float.IsFinite(value) && value > 0f && value <= 50f
            ? value
            : throw new ArgumentOutOfRangeException(nameof(RunMetresPerSecond), value, "a run's speed must be finite, above 0 and at most 50 m/s.");
    } = RunSpeed;

    /// <summary>The jump skill (<see cref="Character.JumpSkill"/>).</summary>
    public int JumpSkill { get => Character.JumpSkill; set => Character.JumpSkill = value; }

    /// <summary>The jump's power, 0..1 (<see cref="Character.JumpPower"/>).</summary>
    public float JumpPower { get => Character.JumpPower; set => Character.JumpPower = value; }

    /// <summary>How high a jump rises at <see cref="JumpPower"/>, metres (<see cref="Character.JumpHeight"/>).</summary>
    public float JumpHeight => Character.JumpHeight(JumpPower);

    /// <summary>Compass heading, radians in [0, 2π): 0 north, π/2 east. A script or mouse-look may set it directly.</summary>
    public float Heading
    {
        get;
        set => field = float.IsFinite(value) ? WrapAngle(value) : throw new ArgumentException($"heading {value} must be finite.", nameof(value));
    }

    /// <summary>Feet position, world metres.</summary>
    public Vector3 Position => Character.Position;

    /// <summary>The cell the player is in, <c>0xXXYYCCCC</c>.</summary>
    public uint CellId => Character.CellId;

    /// <summary>Whether the last step stood on terrain or a floor.</summary>
    public bool IsOnGround => Character.IsOnGround;

    /// <summary>Vertical speed, m/s.</summary>
    public float VerticalSpeed => Character.VerticalSpeed;

    /// <summary>Jumps at <see cref="JumpPower"/> if on the ground and the effects move the body vertically; whether it jumped.</summary>
    public bool Jump() => Character.Jump(JumpPower);

    /// <summary>Advances one frame: turns by the intent over the frame, then moves the character at the intent's velocity.</summary>
    /// <param name="intent">The player's intent, held for the whole frame.</param>
    /// <param name="frameSeconds">Frame time, seconds, ≥ 0 (more than 1 s counts as 1 s).</param>
    /// <exception cref="ArgumentOutOfRangeException">The frame time is negative or not finite.</exception>
    public CharacterStep Update(MovementIntent intent, float frameSeconds)
    {
        if (!float.IsFinite(frameSeconds) || frameSeconds < 0f)
        {
            throw new ArgumentOutOfRangeException(nameof(frameSeconds), frameSeconds, "frame time must be a finite number of seconds ≥ 0.");
        }

        float seconds = MathF.Min(frameSeconds, Character.Settings.MaxFrameSeconds);
        Heading += Math.Clamp(intent.Turn, -1f, 1f) * TurnRate * seconds;
        (float sin, float cos) = MathF.SinCos(Heading);
        Vector2 move = (new Vector2(sin, cos) * Math.Clamp(intent.Forward, -1f, 1f)) + (new Vector2(cos, -sin) * Math.Clamp(intent.Strafe, -1f, 1f));
        move = move.LengthSquared() > 1f ? Vector2.Normalize(move) : move; // diagonal moves are no faster
        CharacterStep step = Character.Update(seconds, move * (intent.Run ? RunMetresPerSecond : WalkSpeed), intent.Jump, MoverId == 0 ? default : _touched);
        _touchedCount = step.TouchedCount;
        return step;
    }

    /// <summary>Puts the player back where the last <see cref="Update"/> found it (<see cref="Character.Undo"/>); the heading stays turned.</summary>
    public void UndoLastUpdate() => Character.Undo();

    private static float WrapAngle(float radians)
    {
        float wrapped = radians % MathF.Tau;
        wrapped = wrapped < 0f ? wrapped + MathF.Tau : wrapped;
        return wrapped < MathF.Tau ? wrapped : 0f;
    }
}
