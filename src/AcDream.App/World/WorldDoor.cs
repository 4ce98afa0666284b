using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;

namespace AcDream.App.World;

/// <summary>A door a scene may register (<c>"doors"</c>): a slab mover (<see cref="MoverKind.Door"/>) standing in a doorway of the world's cells.</summary>
/// <param name="Name">The scene's name for it (<see cref="HoltburgWorld.DoorSets"/>).</param>
/// <param name="Id">Its mover id.</param>
/// <param name="CellId">The cell it stands in, <c>0xXXYYCCCC</c>: its landblock loads and unloads it.</param>
/// <param name="Slab">Its model: a closed box of physics polygons in its own frame.</param>
/// <param name="Shape">The engine's shape of <paramref name="Slab"/> (its walls), built once.</param>
/// <param name="Position">Its origin, world metres (landblock-local in the centre landblock).</param>
/// <param name="Orientation">Its turn about Z.</param>
internal sealed record WorldDoor(string Name, uint Id, uint CellId, GfxObj Slab, MoverShape Shape, Vector3 Position, Quaternion Orientation);
