namespace AcDream.Core.Dat;

/// <summary>Keys of <see cref="Setup.PlacementFrames"/>, with the values stored in the dat (only the one physics reads is named).</summary>
public enum Placement : uint
{
    /// <summary>The default pose: how a static object stands.</summary>
    Default = 0x0,
}
