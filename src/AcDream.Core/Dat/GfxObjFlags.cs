namespace AcDream.Core.Dat;

/// <summary>Flags of a <see cref="GfxObj"/>, with the values stored in the dat.</summary>
[Flags]
public enum GfxObjFlags : uint
{
    /// <summary>No flag set.</summary>
    None = 0x0,

    /// <summary>The object has physics polygons (and a physics BSP).</summary>
    HasPhysics = 0x1,

    /// <summary>The object has drawing polygons (and a drawing BSP).</summary>
    HasDrawing = 0x2,

    /// <summary>The object names a degrade table (<c>DIDDegrade</c>).</summary>
    HasDIDDegrade = 0x8,
}
