using System.Numerics;

namespace AcDream.Core.Dat;

/// <summary>One vertex of a <see cref="VertexArray"/>.</summary>
public sealed class SWVertex
{
    /// <summary>Position in cell-local metres.</summary>
    public Vector3 Origin { get; set; }

    /// <summary>Shading normal (cell-local); physics never reads it: polygon normals come from the winding.</summary>
    public Vector3 Normal { get; set; }
}
