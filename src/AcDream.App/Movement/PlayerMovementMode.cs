using System.Numerics;
using AcDream.Core.Physics;

namespace AcDream.App.Movement;

/// <summary>
/// The Phase B.2 seam: each frame turns the player's intent into a horizontal move, resolves it with
/// <see cref="PhysicsEngine.Resolve(Vector3, uint, Vector3, float, in MovementOptions, out MoveReport)"/> and keeps the resulting position and cell. While the engine
/// reports no ground, a vertical speed accumulates under gravity and lowers the mover; it lands when
/// the engine finds ground at the falling mover's height.
/// </summary>
/// <remarks>
/// Positions are world metres in the engine's frame. Heading is a compass angle in radians: 0 faces
/// north (+Y), π/2 east (+X). A frame longer than <see cref="MaxStepSeconds"/> is split into equal
/// steps no longer than that, so a slow frame does not make one long move through walls or up slopes;
/// a frame longer than <see cref="MaxFrameSeconds"/> is clamped to it.
/// With the literal engine (no <see cref="Effects"/>) Z moves only to the ground found, so a drop
/// onto lower ground (the cellar under a shaft) is a snap. With
/// <see cref="MovementOptions.StepDownHeight"/> set, ground farther below leaves the mover airborne:
/// gravity brings it down, and it lands when its Z reaches the ground (while airborne the mode asks
/// the engine with a step down of 0, so the landing is exact).
/// With <see cref="MovementOptions.Body"/> set (<see cref="MovementOptions.Player"/> has the player's,
/// radius 0.48 m and 1.835 m tall; the default scene uses it) every step moves that body: it stops its
/// radius short of walls and slides along them, and <see cref="Update"/> reports the steps the engine
/// answered <see cref="ResolveOutcome.Slid"/> with the wall's normal. The body is kept while airborne.
/// With <see cref="MovementOptions.Vertical"/> (in <see cref="MovementOptions.Player"/>) the mode moves no Z itself: it
/// passes each step's vertical displacement (exact for constant gravity: the mean of the speeds before and after, times
/// the step) in the delta's Z, and the engine stops the rise under ceilings and lands the fall on the first floor; a
/// head hit (<see cref="ResolveOutcome.Ceiling"/>) zeroes the upward speed, a landing the downward speed. It can jump
/// (<see cref="Jump"/>, <see cref="MovementIntent.Jump"/>).
/// A mover registered in the engine's <see cref="PhysicsEngine.Movers"/> gives its id (<see cref="MoverId"/>): its own
/// walls are then not met by its moves, and each frame records the movers its steps touched (<see cref="Touched"/>).
/// </remarks>
public sealed class PlayerMovementMode
{
    /// <summary>Walking speed: 2 m/s (a placeholder until B.2 reads the player's setup).</summary>
    public const float WalkSpeed = 2f;

    /// <summary>Running speed: 4 m/s (a placeholder until B.2 reads the player's setup).</summary>
    public const float RunSpeed = 4f;

    /// <summary>Turning speed: π/2 rad/s (90° per second).</summary>
    public const float TurnRate = MathF.PI / 2f;

    /// <summary>Highest rise one step may climb: 0.6 m, the player's step up (issue 11; acdream's player uses 0.4–0.6 m).</summary>
    public const float StepUpHeight = 0.6f;

    /// <summary>Gravity: −9.8 m/s² along Z.</summary>
    public const float Gravity = -9.8f;

    /// <summary>Fastest fall: 50 m/s.</summary>
    public const float MaxFallSpeed = 50f;

    /// <summary>Longest physics step: 0.1 s.</summary>
    public const float MaxStepSeconds = 0.1f;

    /// <summary>Longest frame simulated: 1 s, so at most 10 steps; a longer frame is clamped to it (see <see cref="Update"/>).</summary>
    public const float MaxFrameSeconds = 1f;

    /// <summary>Jump skill by default: 100, which jumps 1.64 m at full power (the game's formula: see <see cref="JumpHeight"/>).</summary>
    public const int DefaultJumpSkill = 100;

    /// <summary>The lowest jump: 0.35 m, the game's.</summary>
    public const float MinJumpHeight = 0.35f;

    /// <summary>Most movers one frame records as touched (<see cref="Touched"/>): 16; any more are not recorded.</summary>
    public const int MaxTouched = 16;

    private readonly PhysicsEngine _engine;

    /// <summary><see cref="Effects"/> while airborne: step down 0, so the mover lands only when its Z reaches the ground.</summary>
    private readonly MovementOptions _fallingEffects;

    /// <summary>Whether the engine moves the body vertically (<see cref="MovementOptions.Vertical"/> with a body): the mode passes its fall in the delta.</summary>
    private readonly bool _vertical;

    /// <summary>The movers the last <see cref="Update"/> touched, distinct, in the order first touched; reused every frame.</summary>
    private readonly uint[] _touched = new uint[MaxTouched];
    private int _touchedCount;

    /// <summary>Where the mover stood before the last <see cref="Update"/> (<see cref="UndoLastUpdate"/>).</summary>
    private (Vector3 Position, uint CellId, bool IsOnGround, float VerticalSpeed) _before;

    /// <summary>Places the mover; it starts on the ground, not moving vertically.</summary>
    /// <param name="engine">The engine to resolve against.</param>
    /// <param name="position">Feet position, world metres.</param>
    /// <param name="cellId">The cell at <paramref name="position"/> (<c>0xXXYYCCCC</c>); for outdoors any outdoor number works, the engine recomputes it.</param>
    /// <param name="heading">Compass heading, radians (0 north, π/2 east).</param>
    /// <param name="effects">The engine's opt-in effects this mover uses (default: none, the spec's literal engine with a point mover; <see cref="MovementOptions.Player"/> for a player, with its body).</param>
    /// <exception cref="ArgumentException">The position or heading is not finite.</exception>
    public PlayerMovementMode(PhysicsEngine engine, Vector3 position, uint cellId, float heading, MovementOptions effects = default)
    {
        ArgumentNullException.ThrowIfNull(engine);
        if (!float.IsFinite(position.X) || !float.IsFinite(position.Y) || !float.IsFinite(position.Z) || !float.IsFinite(heading))
        {
            throw new ArgumentException($"position {position} and heading {heading} must be finite.");
        }

        _engine = engine;
        Effects = effects;
        _fallingEffects = effects.StepDownHeight is null ? effects : effects with { StepDownHeight = 0f };
        _vertical = effects.Vertical && effects.Body.HasValue;
        Position = position;
        CellId = cellId;
        Heading = heading;
        IsOnGround = true;
    }

    /// <summary>The engine's opt-in effects this mover uses; see <see cref="MovementOptions"/>.</summary>
    public MovementOptions Effects { get; }

    /// <summary>
    /// The id this mover is registered under in the engine's <see cref="PhysicsEngine.Movers"/>: its steps pass it to
    /// <c>Resolve</c>, so its own walls do not stop it and the rules of who blocks whom read its state, and each
    /// <see cref="Update"/> records the movers touched (<see cref="Touched"/>).
    /// </summary>
    /// <value>0 (the default): not a registered mover; nothing is skipped and no touches are recorded.</value>
    public uint MoverId { get; init; }

    /// <summary>
    /// The ids of the movers the last <see cref="Update"/>'s steps touched (the engine's answer: blocking or not; see
    /// <see cref="PhysicsEngine.Resolve(Vector3, uint, Vector3, float, in MovementOptions, uint, Span{uint}, out int, out MoveReport)"/>),
    /// each once, in the order first touched, at most <see cref="MaxTouched"/>; empty without a <see cref="MoverId"/>.
    /// Valid until the next <see cref="Update"/>.
    /// </summary>
    public ReadOnlySpan<uint> Touched => _touched.AsSpan(0, _touchedCount);

    /// <summary>The speed of a run (<see cref="MovementIntent.Run"/>), metres per second.</summary>
    /// <value><see cref="RunSpeed"/> (4 m/s) by default; up to the game's fastest, 50 m/s.</value>
    /// <exception cref="ArgumentOutOfRangeException">On set: not finite, not above 0, or above <see cref="MaxFallSpeed"/>.</exception>
    public float RunMetresPerSecond
    {
        get;
        init => field = float.IsFinite(value) && value > 0f && value <= MaxFallSpeed
            ? value
            : throw new ArgumentOutOfRangeException(nameof(RunMetresPerSecond), value, "a run's speed must be finite, above 0 and at most 50 m/s.");
    } = RunSpeed;

    /// <summary>The jump skill (the game's character skill), ≥ 0.</summary>
    /// <value><see cref="DefaultJumpSkill"/> (100).</value>
    /// <exception cref="ArgumentOutOfRangeException">On set: negative.</exception>
    public int JumpSkill
    {
        get;
        set => field = value >= 0 ? value : throw new ArgumentOutOfRangeException(nameof(JumpSkill), value, "the jump skill must be ≥ 0.");
    } = DefaultJumpSkill;

    /// <summary>The jump's power, 0..1 (how long the jump key was held, in the game).</summary>
    /// <value>1 (full power).</value>
    /// <exception cref="ArgumentOutOfRangeException">On set: not within 0..1.</exception>
    public float JumpPower
    {
        get;
        set => field = value is >= 0f and <= 1f ? value : throw new ArgumentOutOfRangeException(nameof(JumpPower), value, "the jump's power must be within 0..1.");
    } = 1f;

    /// <summary>
    /// How high a jump rises, metres: the game's (skill / (skill + 1300) · 22.2 + 0.05) · power, at least
    /// <see cref="MinJumpHeight"/> (0.35 m); 1.64 m with the defaults.
    /// </summary>
    public float JumpHeight => MathF.Max(MinJumpHeight, ((JumpSkill / (JumpSkill + 1300f) * 22.2f) + 0.05f) * JumpPower);

    /// <summary>
    /// Jumps if on the ground and the effects move the body vertically (<see cref="MovementOptions.Vertical"/> with a body):
    /// the upward speed becomes √(2 g h) for <see cref="JumpHeight"/> h. Returns whether it jumped.
    /// </summary>
    public bool Jump()
    {
        if (!IsOnGround || !_vertical)
        {
            return false;
        }

        VerticalSpeed = MathF.Sqrt(2f * -Gravity * JumpHeight);
        IsOnGround = false;
        return true;
    }

    /// <summary>Feet position, world metres.</summary>
    public Vector3 Position { get; private set; }

    /// <summary>The cell the mover is in, <c>0xXXYYCCCC</c>.</summary>
    public uint CellId { get; private set; }

    /// <summary>Compass heading, radians in [0, 2π): 0 north, π/2 east. A script or mouse-look may set it directly.</summary>
    public float Heading
    {
        get;
        set => field = float.IsFinite(value) ? WrapAngle(value) : throw new ArgumentException($"heading {value} must be finite.", nameof(value));
    }

    /// <summary>Whether the last step stood on terrain or a floor.</summary>
    public bool IsOnGround { get; private set; }

    /// <summary>Vertical speed, m/s (negative: falling, positive: rising after a jump); 0 on the ground, never below −<see cref="MaxFallSpeed"/>.</summary>
    public float VerticalSpeed { get; private set; }

    /// <summary>
    /// Advances one frame: turns, moves and resolves, in steps of at most <see cref="MaxStepSeconds"/>.
    /// </summary>
    /// <remarks>
    /// Decision: a frame longer than <see cref="MaxFrameSeconds"/> (a stall, a debugger break, a
    /// garbage value) is clamped to it, so one call simulates at most 10 steps and no frame time can
    /// hang the host; the time beyond it is dropped, not caught up.
    /// </remarks>
    /// <param name="intent">The player's intent, held for the whole frame.</param>
    /// <param name="frameSeconds">Frame time, seconds, ≥ 0 (fixed or variable); more than <see cref="MaxFrameSeconds"/> counts as <see cref="MaxFrameSeconds"/>.</param>
    /// <returns>How many steps ran, how many the engine refused and how many it slid along a surface, with the engine's outcome and surface normal of the last refusal and the surface normal of the last slide.</returns>
    /// <exception cref="ArgumentOutOfRangeException">The frame time is negative or not finite.</exception>
    public MovementFrame Update(MovementIntent intent, float frameSeconds)
    {
        if (!float.IsFinite(frameSeconds) || frameSeconds < 0f)
        {
            throw new ArgumentOutOfRangeException(nameof(frameSeconds), frameSeconds, "frame time must be a finite number of seconds ≥ 0.");
        }

        _before = (Position, CellId, IsOnGround, VerticalSpeed);
        _touchedCount = 0;
        if (frameSeconds == 0f)
        {
            return default;
        }

        frameSeconds = MathF.Min(frameSeconds, MaxFrameSeconds);
        int steps = Math.Max(1, (int)MathF.Ceiling(frameSeconds / MaxStepSeconds));
        float dt = frameSeconds / steps;
        int refused = 0, slid = 0, headHits = 0, landings = 0, edges = 0;
        int jumps = intent.Jump && Jump() ? 1 : 0;
        ResolveOutcome? lastRefusal = null;
        Vector3 lastNormal = default, lastSlide = default;
        SurfaceContact wall = default;
        MoveReport report = default;
        for (int i = 0; i < steps; i++)
        {
            bool wasOnGround = IsOnGround;
            ResolveResult result = Step(intent, dt, out report);
            wall = report.Wall.Kind != SurfaceKind.None ? report.Wall : wall;
            headHits += result.Outcome == ResolveOutcome.Ceiling ? 1 : 0;
            landings += !wasOnGround && IsOnGround ? 1 : 0;
            edges += result.Outcome == ResolveOutcome.Edge || report.Wall.Kind == SurfaceKind.FloorEdge ? 1 : 0;
            if (result.IsRefused)
            {
                refused++;
                lastRefusal = result.Outcome;
                lastNormal = result.SurfaceNormal;
            }
            else if (result.Outcome == ResolveOutcome.Slid)
            {
                slid++;
                lastSlide = result.SurfaceNormal;
            }
        }

        return new MovementFrame(steps, refused, lastRefusal, lastNormal, slid, lastSlide, report with { Wall = wall }, jumps, headHits, landings, edges);
    }

    /// <summary>
    /// Puts the mover back where the last <see cref="Update"/> found it: its position, cell, footing and vertical speed
    /// (the heading stays turned). For a host that refuses the engine's answer, such as one of two movers that reached
    /// the same space in one frame, each resolved against where the other stood before it.
    /// </summary>
    public void UndoLastUpdate() => (Position, CellId, IsOnGround, VerticalSpeed) = _before;

    /// <summary>One step of <paramref name="dt"/> seconds; returns the engine's answer and what it met.</summary>
    private ResolveResult Step(MovementIntent intent, float dt, out MoveReport report)
    {
        Heading += Math.Clamp(intent.Turn, -1f, 1f) * TurnRate * dt;
        (float sin, float cos) = MathF.SinCos(Heading);
        var forward = new Vector2(sin, cos);
        var right = new Vector2(cos, -sin);
        Vector2 move = (forward * Math.Clamp(intent.Forward, -1f, 1f)) + (right * Math.Clamp(intent.Strafe, -1f, 1f));
        if (move.LengthSquared() > 1f)
        {
            move = Vector2.Normalize(move); // diagonal moves are no faster
        }

        Vector2 horizontal = move * ((intent.Run ? RunMetresPerSecond : WalkSpeed) * dt);
        var delta = new Vector3(horizontal, 0f);

        ResolveResult result;
        if (_vertical)
        {
            // The engine moves the body up and down: the step's displacement under gravity, exact for a constant
            // acceleration (the mean of the speeds before and after), in the delta's Z.
            if (!IsOnGround || VerticalSpeed > 0f)
            {
                float before = VerticalSpeed;
                VerticalSpeed = MathF.Max(VerticalSpeed + (Gravity * dt), -MaxFallSpeed);
                delta.Z = 0.5f * (before + VerticalSpeed) * dt;
            }

            result = Resolve(Position, delta, Effects, out report);
            if (result.Outcome == ResolveOutcome.Ceiling && VerticalSpeed > 0f)
            {
                VerticalSpeed = 0f; // a head hit
            }
        }
        else
        {
            Vector3 position = Position;
            if (!IsOnGround)
            {
                VerticalSpeed = MathF.Max(VerticalSpeed + (Gravity * dt), -MaxFallSpeed);
                position.Z += VerticalSpeed * dt;
            }

            result = Resolve(position, delta, IsOnGround ? Effects : _fallingEffects, out report);
        }

        Position = result.Position;
        CellId = result.CellId;
        IsOnGround = result.IsOnGround;
        if (result.IsOnGround && VerticalSpeed <= 0f)
        {
            VerticalSpeed = 0f; // a landing, or standing
        }

        return result;
    }

    /// <summary>One call of the engine from <paramref name="position"/> in <see cref="CellId"/>; with a <see cref="MoverId"/>, as that mover, recording what it touched.</summary>
    private ResolveResult Resolve(Vector3 position, Vector3 delta, in MovementOptions effects, out MoveReport report)
    {
        if (MoverId == 0)
        {
            return _engine.Resolve(position, CellId, delta, StepUpHeight, effects, out report);
        }

        Span<uint> touched = stackalloc uint[MaxTouched];
        ResolveResult result = _engine.Resolve(position, CellId, delta, StepUpHeight, effects, MoverId, touched, out int count, out report);
        foreach (uint id in touched[..Math.Min(count, MaxTouched)])
        {
            if (_touchedCount < MaxTouched && Array.IndexOf(_touched, id, 0, _touchedCount) < 0)
            {
                _touched[_touchedCount++] = id;
            }
        }

        return result;
    }

    private static float WrapAngle(float radians)
    {
        float wrapped = radians % MathF.Tau;
        wrapped = wrapped < 0f ? wrapped + MathF.Tau : wrapped;
        return wrapped < MathF.Tau ? wrapped : 0f;
    }
}
