namespace AcDream.Core.Dat;

/// <summary>Flags of a <see cref="CellPortal"/>, with the values stored in the dat.</summary>
[Flags]
public enum PortalFlags : ushort
{
    /// <summary>No flag set.</summary>
    None = 0x0,

    /// <summary>The portal polygon matches the neighbour's portal polygon exactly.</summary>
    ExactMatch = 0x1,

    /// <summary>The portal side bit; the game reads "portal side" as the inverse of this bit.</summary>
    PortalSide = 0x2,
}
