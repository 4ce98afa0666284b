namespace AcDream.Core.Physics;

/// <summary>
/// The mover's body for <see cref="MovementOptions.Body"/>: an upright cylinder of
/// <see cref="Radius"/> standing on the feet point and <see cref="Height"/> tall. Every wall, ceiling
/// or steep polygon that reaches into the cylinder between the step height and the top stops it;
/// lower edges are steps it climbs. See <c>docs/physics.md</c>, "The body".
/// </summary>
public readonly record struct MoverBody
{
    /// <summary>A body of <paramref name="radius"/> and <paramref name="height"/> metres.</summary>
    /// <param name="radius">Metres, finite, &gt; 0.</param>
    /// <param name="height">Metres from the feet to the top, finite, &gt; 0.</param>
    /// <exception cref="ArgumentOutOfRangeException">A value is NaN, infinite, zero or negative.</exception>
    public MoverBody(float radius, float height)
    {
        Radius = float.IsFinite(radius) && radius > 0f
            ? radius
            : throw new ArgumentOutOfRangeException(nameof(radius), radius, "A body's radius must be a finite length > 0 m.");
        Height = float.IsFinite(height) && height > 0f
            ? height
            : throw new ArgumentOutOfRangeException(nameof(height), height, "A body's height must be a finite length > 0 m.");
    }

    /// <summary>The game's player: radius 0.48 m (its spheres'), 1.835 m tall.</summary>
    public static MoverBody Player => new(0.48f, 1.835f);

    /// <summary>Horizontal radius, metres.</summary>
    public float Radius { get; }

    /// <summary>Height above the feet, metres.</summary>
    public float Height { get; }

    /// <summary>Whether this is a real body (not <c>default</c>, whose sizes are zero).</summary>
    internal bool IsValid => Radius > 0f && Height > 0f;
}
