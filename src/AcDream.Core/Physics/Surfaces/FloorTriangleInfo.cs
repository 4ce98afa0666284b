using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>
/// One walkable triangle of a cell's floor as the engine uses it (see <see cref="CellSurface.GetFloorTriangles"/>):
/// landblock-local metres, counter-clockwise seen from above, each vertex's Z on the plane the engine
/// samples.
/// </summary>
/// <param name="A">First vertex, landblock-local metres.</param>
/// <param name="B">Second vertex, landblock-local metres.</param>
/// <param name="C">Third vertex, landblock-local metres.</param>
public readonly record struct FloorTriangleInfo(Vector3 A, Vector3 B, Vector3 C);
