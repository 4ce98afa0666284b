namespace AcDream.Core.Dat;

/// <summary>Flags of an <see cref="EnvCell"/>, with the values stored in the dat.</summary>
[Flags]
public enum EnvCellFlags : uint
{
    /// <summary>No flag set.</summary>
    None = 0x0,

    /// <summary>The outdoors can be seen from this cell.</summary>
    SeenOutside = 0x1,

    /// <summary>The cell lists static objects (stairs and furniture are such objects).</summary>
    HasStaticObjs = 0x2,

    /// <summary>The cell lists weenie objects.</summary>
    HasWeenieObjs = 0x4,

    /// <summary>The cell has a restriction object.</summary>
    HasRestrictionObj = 0x8,
}
