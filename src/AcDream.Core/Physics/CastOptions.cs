namespace AcDream.Core.Physics;

/// <summary>The shape and filters of a cast.</summary>
/// <param name="Radius">The sphere's radius, metres, 0 to <see cref="PhysicsConstants.MaxCastRadius"/> (24 m); 0 is a ray.</param>
/// <param name="Filter">What it passes.</param>
/// <param name="IgnoreId">The id of a registered mover it passes (the player itself); 0: none.</param>
public readonly record struct CastOptions(float Radius, CastFilter Filter = CastFilter.None, uint IgnoreId = 0);
