using System.Numerics;
using AcDream.Core.Physics;

namespace AcDream.App.Scenes;

/// <summary>One segment the engine drew for a frame of the player's walk (<see cref="Character.DebugSink"/>).</summary>
/// <param name="Frame">The frame whose move drew it.</param>
/// <param name="Kind">What it is (a sub-step, a contact, the floor, the support, an edge, a ceiling).</param>
/// <param name="A">One end, world metres.</param>
/// <param name="B">The other end, world metres.</param>
internal readonly record struct DrawnLine(int Frame, DrawKind Kind, Vector3 A, Vector3 B);

/// <summary>
/// The sink the scene runner gives the player's character when the walk is drawn: what each frame's move saw, as the
/// engine draws it (<see cref="PhysicsEngine.DrawMove"/>); a triangle is kept as its three edges. The page shows it.
/// </summary>
internal sealed class FrameDrawing : IDebugSink
{
    private readonly List<DrawnLine> _lines = [];

    /// <summary>The frame being moved; set by the scene runner before the player's move.</summary>
    public int Frame { get; set; }

    /// <summary>Every segment drawn, in frame order.</summary>
    public IReadOnlyList<DrawnLine> Lines => _lines;

    /// <inheritdoc/>
    public void Line(Vector3 a, Vector3 b, DrawKind kind, uint id) => _lines.Add(new DrawnLine(Frame, kind, a, b));

    /// <inheritdoc/>
    public void Triangle(Vector3 a, Vector3 b, Vector3 c, DrawKind kind, uint id)
    {
        Line(a, b, kind, id);
        Line(b, c, kind, id);
        Line(c, a, kind, id);
    }
}
