using System.Numerics;

namespace AcDream.Core.Dat;

/// <summary>
/// A graphics object (portal dat id <c>0x01xxxxxx</c>): one rigid model, in object-local metres
/// (+Z up). Physics reads <see cref="VertexArray"/> and <see cref="PhysicsPolygons"/>; the drawing
/// side (surfaces, drawing polygons and BSPs, degrades) is not modelled.
/// </summary>
public sealed class GfxObj
{
    /// <summary>The object's dat id, <c>0x01xxxxxx</c>.</summary>
    public uint Id { get; set; }

    /// <summary>What the object holds.</summary>
    public GfxObjFlags Flags { get; set; }

    /// <summary>The vertices the polygons refer to, object-local metres.</summary>
    public VertexArray VertexArray { get; set; } = new();

    /// <summary>The collision polygons (floors, walls, roofs together), by id; present when <see cref="GfxObjFlags.HasPhysics"/> is set.</summary>
    public Dictionary<ushort, Polygon> PhysicsPolygons { get; set; } = [];

    /// <summary>The centre the drawing sorts by, object-local metres.</summary>
    public Vector3 SortCenter { get; set; }

    /// <summary>The sphere around the physics polygons (the root of the physics BSP), object-local metres; null when the data has none.</summary>
    public Sphere? BoundingSphere { get; set; }
}
