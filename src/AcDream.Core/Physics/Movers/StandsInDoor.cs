using System.Numerics;
using AcDream.Core.Physics.Surfaces;

namespace AcDream.Core.Physics.Movers;

/// <summary>
/// Whether a mover's cylinder <paramref name="cylinder"/> (a wall polygon with a radius; its frame
/// <paramref name="offset"/> from the door's) overlaps the walls of the door <paramref name="door"/> or stands inside them:
/// the body's question (its swept disc held still), which a commit asks of each closing door. The engine passes the body's
/// answer when it makes the registry, so the committed state needs nothing of the layers above it.
/// </summary>
internal delegate bool StandsInDoor(CellWalls door, in WallPolygon cylinder, Vector2 offset);
