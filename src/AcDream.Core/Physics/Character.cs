using System.Numerics;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics;

/// <summary>
/// A character moved through the engine frame by frame: a wanted horizontal velocity and a jump in, a position, cell,
/// footing and vertical speed out, with gravity, falls, jumps, landings and head hits kept between frames.
/// </summary>
/// <remarks>
/// <para>
/// Positions are world metres in the engine's frame, velocities metres per second. <see cref="Update"/> splits a frame
/// into equal steps of at most <see cref="CharacterSettings.MaxStepSeconds"/> (a frame longer than
/// <see cref="CharacterSettings.MaxFrameSeconds"/> is clamped to it) and resolves each with one
/// <see cref="PhysicsEngine.Resolve(in MoveRequest, Span{uint})"/>.
/// </para>
/// <para>
/// With <see cref="MovementOptions.Vertical"/> and a body (<see cref="MovementOptions.Player"/>) the character moves no Z
/// itself: each step passes its vertical displacement under gravity in the delta's Z (exact for a constant
/// acceleration: the mean of the speeds before and after, times the step), and the engine stops a rise under a ceiling
/// (a head hit zeroes the upward speed) and lands a fall on the first floor (a landing zeroes the downward speed). It can
/// jump (<see cref="Jump"/>). Without, it lowers its own Z under gravity while the engine reports no ground, asking the
/// engine with a step down of 0 so that it lands exactly when its Z reaches the ground.
/// </para>
/// <para>
/// One writer: a character is not safe to update from two threads at once. An update allocates nothing.
/// </para>
/// </remarks>
public sealed class Character
{
    /// <summary>Most steps one frame may be split into: 1,000 (so an update's cost is bounded whatever the settings).</summary>
    public const int MaxStepsPerFrame = 1000;

    /// <summary>The lowest jump: 0.35 m, the game's.</summary>
    public const float MinJumpHeight = 0.35f;

    /// <summary>Most movers one step records as touched: 16 (the rest of a step's are not recorded).</summary>
    private const int StepTouches = 16;

    private readonly PhysicsEngine _engine;
    private readonly MovementOptions _falling; // the options while airborne without vertical motion: step down 0
    private readonly bool _vertical;
    private State _now;
    private State _before;
    private int _jumpSkill;
    private readonly Vector3[] _slides; // each slid step's normal, the last update's; as long as a frame's most steps
    private int _slideCount;
    private float _jumpPower = 1f;

    /// <summary>A character standing at <paramref name="position"/> in <paramref name="cellId"/>, on the ground, not moving vertically.</summary>
    /// <param name="engine">The engine it moves through.</param>
    /// <param name="settings">How it moves (<see cref="CharacterSettings"/>; its defaults are the game's player).</param>
    /// <param name="position">Feet position, world metres.</param>
    /// <param name="cellId">The cell at <paramref name="position"/> (<c>0xXXYYCCCC</c>); outdoors any outdoor number works, the engine recomputes it.</param>
    /// <exception cref="ArgumentNullException">The engine or settings are null.</exception>
    /// <exception cref="ArgumentException">A setting is out of range (named), or the position is not finite.</exception>
    public Character(PhysicsEngine engine, CharacterSettings settings, Vector3 position, uint cellId)
    {
        ArgumentNullException.ThrowIfNull(engine);
        ArgumentNullException.ThrowIfNull(settings);
        settings.Validate();
        if (!(float.IsFinite(position.X) && float.IsFinite(position.Y) && float.IsFinite(position.Z)))
        {
            throw new ArgumentException($"position {position} (cell 0x{cellId:X8}) must be finite.", nameof(position));
        }

        _engine = engine;
        Settings = settings;
        MovementOptions options = settings.Options;
        _falling = options.StepDownHeight is null ? options : options with { StepDownHeight = 0f };
        _vertical = options.Vertical && options.Body.HasValue;
        _now = new State(position, cellId, true, 0f);
        _before = _now;
        _jumpSkill = settings.JumpSkill;
        _slides = new Vector3[Math.Max(1, (int)MathF.Ceiling(settings.MaxFrameSeconds / settings.MaxStepSeconds))];
    }

    /// <summary>How it moves.</summary>
    public CharacterSettings Settings { get; }

    /// <summary>Feet position, world metres.</summary>
    public Vector3 Position => _now.Position;

    /// <summary>The cell it is in, <c>0xXXYYCCCC</c>.</summary>
    public uint CellId => _now.CellId;

    /// <summary>Whether the last step stood on terrain or a floor.</summary>
    public bool IsOnGround => _now.IsOnGround;

    /// <summary>Vertical speed, m/s (negative: falling, positive: rising); 0 on the ground, never below −<see cref="CharacterSettings.MaxFallSpeed"/>.</summary>
    public float VerticalSpeed => _now.VerticalSpeed;

    /// <summary>The jump skill (the game's character skill), ≥ 0; starts as <see cref="CharacterSettings.JumpSkill"/> and may change (a buff, a new level).</summary>
    /// <exception cref="ArgumentOutOfRangeException">On set: negative.</exception>
    public int JumpSkill
    {
        get => _jumpSkill;
        set => _jumpSkill = value >= 0 ? value : throw new ArgumentOutOfRangeException(nameof(JumpSkill), value, "the jump skill must be ≥ 0.");
    }

    /// <summary>The power of the jumps <see cref="Update"/> takes, 0..1 (how long the jump key was held, in the game): 1 by default.</summary>
    /// <exception cref="ArgumentOutOfRangeException">On set: not within 0..1.</exception>
    public float JumpPower
    {
        get => _jumpPower;
        set => _jumpPower = value is >= 0f and <= 1f ? value : throw new ArgumentOutOfRangeException(nameof(JumpPower), value, "a jump's power must be within 0..1.");
    }

    /// <summary>
    /// The surface normal of each step the last <see cref="Update"/> slid along a wall or a slope (<see cref="CharacterStep.SlidSteps"/>
    /// of them), in step order: a wall's is horizontal and faces the character. Valid until the next update.
    /// </summary>
    public ReadOnlySpan<Vector3> SlideNormals => _slides.AsSpan(0, _slideCount);

    /// <summary>
    /// Where each step's move draws what it saw (<see cref="PhysicsEngine.DrawMove"/>: its sub-steps, contacts, floor or
    /// support, edge, ceiling), the answers unchanged; null (the default): nothing drawn, one untaken branch a step.
    /// </summary>
    public IDebugSink? DebugSink { get; set; }

    /// <summary>Whether it can jump: its effects move the body vertically (<see cref="MovementOptions.Vertical"/> with a body).</summary>
    public bool CanJump => _vertical;

    /// <summary>
    /// How high a jump of <paramref name="power"/> rises, metres: the game's (skill / (skill + 1300) · 22.2 + 0.05) · power, at
    /// least <see cref="MinJumpHeight"/>; 1.64 m at full power with skill 100.
    /// </summary>
    /// <param name="power">The jump's power, 0..1 (how long the jump key was held, in the game).</param>
    /// <exception cref="ArgumentOutOfRangeException">The power is not within 0..1.</exception>
    public float JumpHeight(float power = 1f)
    {
        if (!(power is >= 0f and <= 1f))
        {
            throw new ArgumentOutOfRangeException(nameof(power), power, "a jump's power must be within 0..1.");
        }

        int skill = _jumpSkill;
        return MathF.Max(MinJumpHeight, ((skill / (skill + 1300f) * 22.2f) + 0.05f) * power);
    }

    /// <summary>
    /// Jumps if on the ground and <see cref="CanJump"/>: the upward speed becomes √(2 g h) for the
    /// <see cref="JumpHeight"/> h of <paramref name="power"/>. Returns whether it jumped.
    /// </summary>
    /// <param name="power">The jump's power, 0..1.</param>
    /// <exception cref="ArgumentOutOfRangeException">The power is not within 0..1.</exception>
    public bool Jump(float power)
    {
        float height = JumpHeight(power);
        if (!_now.IsOnGround || !_vertical)
        {
            return false;
        }

        _now = _now with { IsOnGround = false, VerticalSpeed = MathF.Sqrt(2f * Settings.Gravity * height) };
        return true;
    }

    /// <summary>Moves one frame: <paramref name="seconds"/> at <paramref name="velocity"/>, jumping first when <paramref name="jump"/> asks and it can.</summary>
    /// <param name="seconds">Frame time, seconds, ≥ 0; more than <see cref="CharacterSettings.MaxFrameSeconds"/> counts as that.</param>
    /// <param name="velocity">The wanted horizontal velocity, world X and Y, metres per second; the engine stops or slides it.</param>
    /// <param name="jump">Whether to jump first, at <see cref="JumpPower"/> (<see cref="Jump"/>; an <see cref="Undo"/> takes the jump back too).</param>
    /// <param name="touched">Where to write the ids of the registered movers the steps touched (each once, in the order met along the path); empty: not looked for. Needs <see cref="CharacterSettings.MoverId"/>.</param>
    /// <returns>Where it is now and what the steps met.</returns>
    /// <exception cref="ArgumentOutOfRangeException">The frame time is negative or not finite, or the velocity is not finite.</exception>
    public CharacterStep Update(float seconds, Vector2 velocity, bool jump, Span<uint> touched = default)
    {
        if (!float.IsFinite(seconds) || seconds < 0f)
        {
            throw new ArgumentOutOfRangeException(nameof(seconds), seconds, "frame time must be a finite number of seconds ≥ 0.");
        }

        if (!(float.IsFinite(velocity.X) && float.IsFinite(velocity.Y)))
        {
            throw new ArgumentOutOfRangeException(nameof(velocity), velocity, "the velocity must be finite.");
        }

        _before = _now;
        _slideCount = 0;
        if (seconds == 0f)
        {
            return Step(default);
        }

        seconds = MathF.Min(seconds, Settings.MaxFrameSeconds);
        int steps = Math.Max(1, (int)MathF.Ceiling(seconds / Settings.MaxStepSeconds));
        float dt = seconds / steps;
        var frame = new Frame { Steps = steps, Jumps = jump && Jump(_jumpPower) ? 1 : 0 };
        for (int i = 0; i < steps; i++)
        {
            bool wasOnGround = _now.IsOnGround;
            ResolveResult result = Move(velocity * dt, dt, touched, ref frame, out MoveReport report);
            frame.Add(in result, in report, !wasOnGround && _now.IsOnGround);
            if (result.Outcome == ResolveOutcome.Slid && !result.IsRefused && _slideCount < _slides.Length)
            {
                _slides[_slideCount++] = result.SurfaceNormal;
            }
        }

        return Step(in frame);
    }

    /// <summary>
    /// Puts the character at <paramref name="position"/> in <paramref name="cellId"/> (a teleport, or a server's
    /// correction): on a floor within its step below or above, else in the air there; not moving vertically.
    /// </summary>
    /// <param name="position">Feet position, world metres.</param>
    /// <param name="cellId">The cell at <paramref name="position"/>.</param>
    /// <returns>Where it stands: the engine's answer for it standing still there.</returns>
    /// <exception cref="ArgumentException">The position is not finite, the cell is not a cell of the world (as <c>Resolve</c>), or its body there would be inside a wall (<paramref name="position"/> named, with how deep).</exception>
    public ResolveResult Place(Vector3 position, uint cellId)
    {
        if (!(float.IsFinite(position.X) && float.IsFinite(position.Y) && float.IsFinite(position.Z)))
        {
            throw new ArgumentException($"position {position} (cell 0x{cellId:X8}) must be finite.", nameof(position));
        }

        float step = Settings.StepUpHeight;
        if (_engine.TryGetGround(position, cellId, step, out float ground, out _, out _) && ground >= position.Z - step)
        {
            position.Z = ground; // a floor within its step: stand on it
        }

        if (Settings.Options.Body is MoverBody body && _engine.BodyOverlap(position, cellId, step, body) is float depth and > 0f)
        {
            throw new ArgumentException($"position {position} (cell 0x{cellId:X8}) puts the body {depth} m inside a wall.", nameof(position));
        }

        MoveResult placed = _engine.Resolve(new MoveRequest(position, cellId, Vector3.Zero, step) { Options = Settings.Options, MoverId = Settings.MoverId });
        _before = _now;
        _now = new State(placed.Answer.Position, placed.Answer.CellId, placed.Answer.IsOnGround, 0f);
        return placed.Answer;
    }

    /// <summary>
    /// Puts the character back where the last <see cref="Update"/> or <see cref="Place"/> found it: position, cell, footing
    /// and vertical speed. For a host that refuses the engine's answer, such as one of two movers that reached the same
    /// space in one frame, each resolved against where the other stood before it.
    /// </summary>
    public void Undo() => _now = _before;

    /// <summary>One step of <paramref name="dt"/> seconds moving <paramref name="horizontal"/>; the engine's answer.</summary>
    private ResolveResult Move(Vector2 horizontal, float dt, Span<uint> touched, ref Frame frame, out MoveReport report)
    {
        var delta = new Vector3(horizontal, 0f);
        Vector3 position = _now.Position;
        float speed = _now.VerticalSpeed;
        MovementOptions options = Settings.Options;
        if (_vertical)
        {
            // The engine moves the body up and down: the step's displacement under gravity, exact for a constant
            // acceleration (the mean of the speeds before and after), in the delta's Z.
            if (!_now.IsOnGround || speed > 0f)
            {
                float before = speed;
                speed = MathF.Max(speed - (Settings.Gravity * dt), -Settings.MaxFallSpeed);
                delta.Z = 0.5f * (before + speed) * dt;
            }
        }
        else if (!_now.IsOnGround)
        {
            speed = MathF.Max(speed - (Settings.Gravity * dt), -Settings.MaxFallSpeed);
            position.Z += speed * dt;
            options = _falling;
        }

        ResolveResult result = Resolve(position, delta, in options, touched, ref frame, out report);
        if (_vertical && result.Outcome == ResolveOutcome.Ceiling && speed > 0f)
        {
            speed = 0f; // a head hit
        }

        if (result.IsOnGround && speed <= 0f)
        {
            speed = 0f; // a landing, or standing
        }

        _now = new State(result.Position, result.CellId, result.IsOnGround, speed);
        return result;
    }

    /// <summary>One call of the engine; with a mover id and a span, the movers touched merged into it, first met first.</summary>
    private ResolveResult Resolve(Vector3 position, Vector3 delta, in MovementOptions options, Span<uint> touched, ref Frame frame, out MoveReport report)
    {
        var request = new MoveRequest(position, _now.CellId, delta, Settings.StepUpHeight) { Options = options, MoverId = Settings.MoverId, WithReport = true };
        if (Settings.MoverId == 0 || touched.IsEmpty)
        {
            MoveResult plain = DebugSink is IDebugSink drawn ? _engine.DrawMove(in request, drawn) : _engine.Resolve(in request);
            report = plain.Report;
            return plain.Answer;
        }

        Span<uint> step = stackalloc uint[StepTouches];
        MoveResult result = DebugSink is IDebugSink sink ? _engine.DrawMove(in request, sink, step) : _engine.Resolve(in request, step);
        foreach (uint id in step[..Math.Min(result.TouchedCount, StepTouches)])
        {
            if (frame.TouchedCount < touched.Length && !touched[..frame.TouchedCount].Contains(id))
            {
                touched[frame.TouchedCount++] = id;
            }
        }

        report = result.Report;
        return result.Answer;
    }

    private CharacterStep Step(in Frame frame) => new()
    {
        Position = _now.Position,
        CellId = _now.CellId,
        IsOnGround = _now.IsOnGround,
        VerticalSpeed = _now.VerticalSpeed,
        Steps = frame.Steps,
        RefusedSteps = frame.Refused,
        LastRefusal = frame.LastRefusal,
        LastRefusalNormal = frame.LastRefusalNormal,
        SlidSteps = frame.Slid,
        LastSlideNormal = frame.LastSlideNormal,
        Met = frame.Report with { Wall = frame.Wall },
        Jumps = frame.Jumps,
        HeadHits = frame.HeadHits,
        Landings = frame.Landings,
        EdgeSlides = frame.Edges,
        TouchedCount = frame.TouchedCount,
    };

    /// <summary>Where the character is: feet, cell, footing and vertical speed.</summary>
    private readonly record struct State(Vector3 Position, uint CellId, bool IsOnGround, float VerticalSpeed);

    /// <summary>What a frame's steps met, gathered step by step.</summary>
    private struct Frame
    {
        public int Steps, Refused, Slid, Jumps, HeadHits, Landings, Edges, TouchedCount;
        public ResolveOutcome? LastRefusal;
        public Vector3 LastRefusalNormal, LastSlideNormal;
        public SurfaceContact Wall;
        public MoveReport Report;

        public void Add(in ResolveResult result, in MoveReport report, bool landed)
        {
            Report = report;
            Wall = report.Wall.Kind != SurfaceKind.None ? report.Wall : Wall;
            HeadHits += result.Outcome == ResolveOutcome.Ceiling ? 1 : 0;
            Landings += landed ? 1 : 0;
            Edges += result.Outcome == ResolveOutcome.Edge || report.Wall.Kind == SurfaceKind.FloorEdge ? 1 : 0;
            if (result.IsRefused)
            {
                Refused++;
                LastRefusal = result.Outcome;
                LastRefusalNormal = result.SurfaceNormal;
            }
            else if (result.Outcome == ResolveOutcome.Slid)
            {
                Slid++;
                LastSlideNormal = result.SurfaceNormal;
            }
        }
    }
}
