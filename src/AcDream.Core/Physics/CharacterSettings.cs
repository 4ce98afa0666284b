namespace AcDream.Core.Physics;

/// <summary>
/// How a <see cref="Character"/> moves: the engine's effects and step, gravity, the fastest fall, the jump skill, how a
/// frame is cut into steps, and the id it is registered under. The defaults are the game's player.
/// </summary>
/// <remarks>Checked when a <see cref="Character"/> is made from it: a value out of range is an <see cref="ArgumentException"/> naming the setting.</remarks>
public sealed record CharacterSettings
{
    /// <summary>
    /// The engine's effects each step uses (<see cref="MovementOptions"/>): the body, step down, walkable slope, sweep,
    /// doors only, vertical motion, footing and edge slide. Default: <see cref="MovementOptions.Player"/>, all of them,
    /// with the player's body (radius 0.48 m, 1.835 m tall). With <see cref="MovementOptions.Vertical"/> and a body the
    /// engine moves the body up and down (jumps stop at ceilings, falls land on the first floor); without, the character
    /// moves its own Z under gravity and lands when the engine finds ground at its height (no jumps).
    /// </summary>
    public MovementOptions Options { get; init; } = MovementOptions.Player;

    /// <summary>Highest rise one step may climb, metres ≥ 0: 0.6 m (the game's player).</summary>
    public float StepUpHeight { get; init; } = 0.6f;

    /// <summary>Gravity's acceleration, m/s² downward (along −Z), ≥ 0: 9.8.</summary>
    public float Gravity { get; init; } = 9.8f;

    /// <summary>Fastest fall, m/s, above 0: 50 (the game's).</summary>
    public float MaxFallSpeed { get; init; } = 50f;

    /// <summary>The jump skill (the game's character skill), ≥ 0: 100, which jumps 1.64 m at full power (see <see cref="Character.JumpHeight"/>).</summary>
    public int JumpSkill { get; init; } = 100;

    /// <summary>Longest physics step, seconds, above 0: 0.1. A frame is split into equal steps no longer than it, so a slow frame does not make one long move through walls or up slopes.</summary>
    public float MaxStepSeconds { get; init; } = 0.1f;

    /// <summary>Longest frame simulated, seconds, at least <see cref="MaxStepSeconds"/>: 1. A longer frame (a stall, a debugger's break) is clamped to it; the time beyond it is dropped, not caught up.</summary>
    public float MaxFrameSeconds { get; init; } = 1f;

    /// <summary>The id the character is registered under in <see cref="PhysicsEngine.Movers"/> (its own walls are then not met, and the movers it touches are recorded); 0 (the default): not registered.</summary>
    public uint MoverId { get; init; }

    /// <summary>Throws when a setting is out of range, naming it.</summary>
    internal void Validate()
    {
        static void Check(bool ok, string name, object value, string rule)
        {
            if (!ok)
            {
                throw new ArgumentOutOfRangeException("settings", value, $"settings.{name} {value} {rule}.");
            }
        }

        Check(float.IsFinite(StepUpHeight) && StepUpHeight >= 0f, nameof(StepUpHeight), StepUpHeight, "must be a finite height ≥ 0 m");
        Check(float.IsFinite(Gravity) && Gravity >= 0f, nameof(Gravity), Gravity, "must be a finite acceleration ≥ 0 m/s²");
        Check(float.IsFinite(MaxFallSpeed) && MaxFallSpeed > 0f, nameof(MaxFallSpeed), MaxFallSpeed, "must be a finite speed above 0 m/s");
        Check(JumpSkill >= 0, nameof(JumpSkill), JumpSkill, "must be ≥ 0");
        Check(float.IsFinite(MaxStepSeconds) && MaxStepSeconds > 0f, nameof(MaxStepSeconds), MaxStepSeconds, "must be a finite time above 0 s");
        Check(float.IsFinite(MaxFrameSeconds) && MaxFrameSeconds >= MaxStepSeconds && MaxFrameSeconds / MaxStepSeconds <= Character.MaxStepsPerFrame,
            nameof(MaxFrameSeconds), MaxFrameSeconds, $"must be finite, at least MaxStepSeconds and at most {Character.MaxStepsPerFrame} of them");
    }
}
