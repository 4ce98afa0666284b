using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>What one <see cref="Character.Update"/> did: where the character is now, and what its steps met.</summary>
public readonly record struct CharacterStep
{
    /// <summary>Feet position after the frame, world metres.</summary>
    public Vector3 Position { get; init; }

    /// <summary>The cell the character is in after the frame, <c>0xXXYYCCCC</c>.</summary>
    public uint CellId { get; init; }

    /// <summary>Whether the last step stood on terrain or a floor.</summary>
    public bool IsOnGround { get; init; }

    /// <summary>Vertical speed after the frame, m/s (negative: falling, positive: rising); 0 on the ground.</summary>
    public float VerticalSpeed { get; init; }

    /// <summary>Physics steps taken: 0 for a zero-length frame, else at least 1 (the frame, clamped, split into steps of at most <see cref="CharacterSettings.MaxStepSeconds"/>).</summary>
    public int Steps { get; init; }

    /// <summary>Steps the engine refused (<see cref="ResolveResult.IsRefused"/>); with swept moves a step stopped part way counts.</summary>
    public int RefusedSteps { get; init; }

    /// <summary>The engine's outcome of the last refused step; null when none was refused.</summary>
    public ResolveOutcome? LastRefusal { get; init; }

    /// <summary>The surface normal of the last refused step (zero when the engine names none, or none was refused).</summary>
    public Vector3 LastRefusalNormal { get; init; }

    /// <summary>Steps the engine answered <see cref="ResolveOutcome.Slid"/>: the body touched a wall (or a slope too steep) and moved on along it.</summary>
    public int SlidSteps { get; init; }

    /// <summary>The surface normal of the last slid step: a wall's unit normal (horizontal, towards the character) or a slope's; zero when none slid. Every slid step's normal, in order: <see cref="Character.SlideNormals"/>.</summary>
    public Vector3 LastSlideNormal { get; init; }

    /// <summary>What the steps met (<see cref="MoveReport"/>): the floor the last step stands on, and the wall, shell, cylinder or mover of the last step that one stopped or slid.</summary>
    public MoveReport Met { get; init; }

    /// <summary>Jumps taken this frame (0 or 1).</summary>
    public int Jumps { get; init; }

    /// <summary>Steps whose rise the engine stopped under a surface (<see cref="ResolveOutcome.Ceiling"/>); each zeroes the upward speed.</summary>
    public int HeadHits { get; init; }

    /// <summary>Steps that ended on the ground after the character was in the air.</summary>
    public int Landings { get; init; }

    /// <summary>Steps the engine held at an edge (<see cref="ResolveOutcome.Edge"/>, or slid along a floor's edge).</summary>
    public int EdgeSlides { get; init; }

    /// <summary>How many distinct movers the steps touched, written into the caller's span in the order met along the path (at most its length).</summary>
    public int TouchedCount { get; init; }

    /// <summary>Whether the frame landed (<see cref="Landings"/> above 0).</summary>
    public bool Landed => Landings > 0;

    /// <summary>Whether a ceiling stopped a rise this frame (<see cref="HeadHits"/> above 0).</summary>
    public bool HeadHit => HeadHits > 0;

    /// <summary>Whether an edge held the character this frame (<see cref="EdgeSlides"/> above 0).</summary>
    public bool HeldAtEdge => EdgeSlides > 0;
}
