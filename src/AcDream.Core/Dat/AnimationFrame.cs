namespace AcDream.Core.Dat;

/// <summary>One pose of a <see cref="Setup"/>: a frame per part, in the order of <see cref="Setup.Parts"/>.</summary>
public sealed class AnimationFrame
{
    /// <summary>Part-local → setup-local placement of each part.</summary>
    public List<Frame> Frames { get; set; } = [];
}
