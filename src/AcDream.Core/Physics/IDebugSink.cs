using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>
/// Where the engine draws what it has and what a move saw (<see cref="PhysicsEngine.DrawNear{TSink}(Vector3, uint, float, ref TSink)"/>,
/// <see cref="PhysicsEngine.DrawMove(in MoveRequest, IDebugSink, Span{uint})"/>): the caller implements it and routes the lines and
/// triangles to its own renderer.
/// </summary>
/// <remarks>
/// Points are world metres in the engine's frame (+X east, +Y north, +Z up), each rounded to a float at its magnitude
/// (about 2–4 mm far from the origin of the global frame; a frame centred on a landblock keeps them within 1e-4 m of the
/// geometry). The engine calls the sink on the calling thread, during the call, and allocates nothing per call; the sink
/// should not call back into the engine.
/// </remarks>
public interface IDebugSink
{
    /// <summary>A segment from <paramref name="a"/> to <paramref name="b"/>, world metres.</summary>
    /// <param name="a">One end, world metres.</param>
    /// <param name="b">The other end, world metres.</param>
    /// <param name="kind">What it is part of (see <see cref="DrawKind"/> for each kind's id and its segment).</param>
    /// <param name="id">Whose it is: a cell, object, mover or landblock id, as <see cref="DrawKind"/> says.</param>
    void Line(Vector3 a, Vector3 b, DrawKind kind, uint id);

    /// <summary>A triangle <paramref name="a"/>, <paramref name="b"/>, <paramref name="c"/>, world metres, counter-clockwise seen from above for floors and terrain.</summary>
    /// <param name="a">A corner, world metres.</param>
    /// <param name="b">A corner, world metres.</param>
    /// <param name="c">A corner, world metres.</param>
    /// <param name="kind">What it is part of (see <see cref="DrawKind"/>).</param>
    /// <param name="id">Whose it is, as <see cref="DrawKind"/> says.</param>
    void Triangle(Vector3 a, Vector3 b, Vector3 c, DrawKind kind, uint id);
}
