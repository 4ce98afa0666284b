using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>One wall of an <see cref="ObjectSurface"/> seen by a caller: a polygon's outline (landblock-local metres), or a cylinder (<see cref="Radius"/> > 0: its axis from bottom to top).</summary>
/// <param name="Outline">The polygon's vertices, or a cylinder's bottom and top centre.</param>
/// <param name="Radius">0 for a polygon; a cylinder's radius, metres.</param>
public sealed record ObjectWallInfo(Vector3[] Outline, float Radius);
