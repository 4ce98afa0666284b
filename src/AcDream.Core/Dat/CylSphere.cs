using System.Numerics;

namespace AcDream.Core.Dat;

/// <summary>
/// An upright collision cylinder of a <see cref="Setup"/> (trees, posts): it stands on
/// <see cref="Origin"/> (its bottom centre, setup-local metres) and rises <see cref="Height"/> metres.
/// </summary>
public sealed class CylSphere
{
    /// <summary>Bottom centre, setup-local metres.</summary>
    public Vector3 Origin { get; set; }

    /// <summary>Radius, metres.</summary>
    public float Radius { get; set; }

    /// <summary>Height above <see cref="Origin"/>, metres.</summary>
    public float Height { get; set; }
}
