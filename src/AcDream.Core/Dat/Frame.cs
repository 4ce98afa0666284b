using System.Numerics;

namespace AcDream.Core.Dat;

/// <summary>
/// A placement: <see cref="Origin"/> plus <see cref="Orientation"/>. A point v of the child frame is
/// <c>Origin + Vector3.Transform(v, Orientation)</c> in the parent frame.
/// </summary>
public sealed class Frame
{
    /// <summary>Translation in metres, in the parent frame (landblock-local for an EnvCell).</summary>
    public Vector3 Origin { get; set; }

    /// <summary>
    /// Rotation of the child frame. Stored on disk as W, X, Y, Z, i.e. <c>new Quaternion(x, y, z, w)</c>;
    /// stored values may be slightly non-unit.
    /// </summary>
    public Quaternion Orientation { get; set; } = Quaternion.Identity;
}
