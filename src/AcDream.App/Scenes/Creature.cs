using System.Numerics;
using AcDream.App.Movement;

namespace AcDream.App.Scenes;

/// <summary>
/// A scene's creature as the runner walks it: its mover id, its walk (a <see cref="PlayerMovementMode"/> with its own
/// id and the player's effects, so the engine answers each of its moves) while its landblock is loaded, the intents its
/// seed draws, and its path.
/// </summary>
/// <remarks>
/// A wandering creature holds each intent for <see cref="MinHoldFrames"/>..<see cref="MaxHoldFrames"/> frames: one in
/// <see cref="StandOneIn"/> stands, the others walk a heading drawn at random. Once it is farther from home than it
/// wanders while walking away from home, it turns at once and walks home (within <see cref="HomeSpread"/> of the
/// straight line) for <see cref="MinHoldFrames"/>..2 × <see cref="MinHoldFrames"/> frames, so it strays at most a
/// frame's walk (about 7 cm) beyond its ground. A creature that does not wander stands. The draws come from
/// <see cref="Random(int)"/> with its seed, in frame order, so every run draws the same.
/// </remarks>
internal sealed class Creature
{
    /// <summary>Shortest an intent is held: 30 frames (1 s).</summary>
    public const int MinHoldFrames = 30;

    /// <summary>Longest a wandering intent is held: 120 frames (4 s).</summary>
    public const int MaxHoldFrames = 120;

    /// <summary>One wandering intent in 4 stands.</summary>
    public const int StandOneIn = 4;

    /// <summary>How far a walk home may turn from the straight line: ±30° (π/6 rad each way).</summary>
    public const float HomeSpread = MathF.PI / 6f;

    private readonly Random _random;
    private readonly List<CreatureSample> _samples = [];
    private readonly List<(int Frame, uint LandblockId)> _removed = [];
    private int _framesLeft;
    private bool _walking;

    /// <summary>A creature not yet in the world: it appears when its home's landblock loads (<see cref="Appear"/>).</summary>
    public Creature(uint id, SceneCreature creature)
    {
        Id = id;
        Scene = creature;
        _random = new Random(creature.Seed);
    }

    /// <summary>Its mover id.</summary>
    public uint Id { get; }

    /// <summary>What the scene says of it.</summary>
    public SceneCreature Scene { get; }

    /// <summary>Its walk while it is in the world; null while its landblock is not loaded.</summary>
    public PlayerMovementMode? Mode { get; private set; }

    /// <summary>Frames it was held back: its answer ended inside a mover that had already moved that frame.</summary>
    public int HeldBack { get; private set; }

    /// <summary>It appears (its landblock loaded) at frame <paramref name="frame"/>, walking with <paramref name="mode"/>.</summary>
    public void Appear(PlayerMovementMode mode, int frame)
    {
        Mode = mode;
        _framesLeft = 0;
        Record(frame);
    }

    /// <summary>It leaves the world with landblock <paramref name="landblockId"/>, unloaded at frame <paramref name="frame"/>.</summary>
    public void Disappear(int frame, uint landblockId)
    {
        Mode = null;
        _removed.Add((frame, landblockId));
    }

    /// <summary>One frame: a new intent when the last has run out, then the move the engine answers.</summary>
    public void Step(float dt)
    {
        PlayerMovementMode mode = Mode ?? throw new InvalidOperationException($"creature 0x{Id:X8} is not in the world.");
        Vector2 home = Scene.Home - new Vector2(mode.Position.X, mode.Position.Y);
        (float sin, float cos) = MathF.SinCos(mode.Heading);
        bool astray = _walking && home.Length() > Scene.Wander && Vector2.Dot(home, new Vector2(sin, cos)) < 0f;
        if (--_framesLeft <= 0 || astray)
        {
            Decide(mode);
        }

        mode.Update(new MovementIntent(_walking ? 1f : 0f, 0f, 0f, Run: false), dt);
    }

    /// <summary>Puts it back where it stood before this frame's move (<see cref="PlayerMovementMode.UndoLastUpdate"/>).</summary>
    public void HoldBack()
    {
        Mode!.UndoLastUpdate();
        HeldBack++;
    }

    /// <summary>Records where it is after frame <paramref name="frame"/>.</summary>
    public void Record(int frame) => _samples.Add(new CreatureSample(frame, Mode!.Position, Mode.CellId));

    /// <summary>Its walk so far.</summary>
    public CreaturePath Path() => new(Id, Scene, _samples, HeldBack, _removed);

    private void Decide(PlayerMovementMode mode)
    {
        if (Scene.Wander <= 0f)
        {
            (_walking, _framesLeft) = (false, int.MaxValue);
            return;
        }

        Vector2 home = Scene.Home - new Vector2(mode.Position.X, mode.Position.Y);
        if (home.Length() > Scene.Wander)
        {
            mode.Heading = MathF.Atan2(home.X, home.Y) + ((_random.NextSingle() - 0.5f) * 2f * HomeSpread);
            (_walking, _framesLeft) = (true, _random.Next(MinHoldFrames, (2 * MinHoldFrames) + 1));
            return;
        }

        _framesLeft = _random.Next(MinHoldFrames, MaxHoldFrames + 1);
        _walking = _random.Next(StandOneIn) != 0;
        if (_walking)
        {
            mode.Heading = _random.NextSingle() * MathF.Tau;
        }
    }
}
