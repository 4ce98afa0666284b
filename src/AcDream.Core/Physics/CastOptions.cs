namespace AcDream.Core.Physics;

/// <summary>The shape and filters of a cast.</summary>
/// <param name="Radius">The sphere's radius, metres, 0 to <see cref="PhysicsConstants.MaxCastRadius"/> (24 m); 0 is a ray.</param>
/// <param name="Filter">What it passes.</param>
/// <remarks>The mover a cast ignores (its caster) is named in its request, as a move's is: <see cref="CastRequest.MoverId"/>.</remarks>
public readonly record struct CastOptions(float Radius, CastFilter Filter = CastFilter.None);
