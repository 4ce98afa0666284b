using System.Numerics;

namespace AcDream.Core.Dat;

/// <summary>A sphere: <see cref="Origin"/> and <see cref="Radius"/>, metres, in the frame of the object that holds it.</summary>
public sealed class Sphere
{
    /// <summary>Centre, metres.</summary>
    public Vector3 Origin { get; set; }

    /// <summary>Radius, metres.</summary>
    public float Radius { get; set; }
}
