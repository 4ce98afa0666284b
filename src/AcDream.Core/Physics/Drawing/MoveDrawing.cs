using System.Numerics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics.Drawing;

/// <summary>
/// What a move saw, drawn while it is decided: the sink of the thread's <see cref="PhysicsEngine.DrawMove"/> call, read only
/// at the few points where a sub-step, a contact, an edge or a ceiling is decided. With no such call running on any
/// thread, each hook is one read of a static field and a branch not taken; the answer never reads what is drawn.
/// </summary>
internal static class MoveDrawing
{
    /// <summary>How many <see cref="PhysicsEngine.DrawMove"/> calls are running, on all threads.</summary>
    private static int s_running;

    [ThreadStatic]
    private static IDebugSink? t_sink;

    [ThreadStatic]
    private static uint t_id;

    [ThreadStatic]
    private static Vector3 t_last;

    /// <summary>Whether a move on this thread is being drawn (one static read when none is anywhere).</summary>
    public static bool On
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        get => Volatile.Read(ref s_running) != 0 && t_sink is not null;
    }

    /// <summary>Starts drawing this thread's move into <paramref name="sink"/> as the mover <paramref name="id"/>, from <paramref name="start"/>.</summary>
    public static void Begin(IDebugSink sink, uint id, Vector3 start)
    {
        (t_sink, t_id, t_last) = (sink, id, start);
        Interlocked.Increment(ref s_running);
    }

    /// <summary>Ends it: <paramref name="last"/>, where the last sub-step drawn ended (the start when none was).</summary>
    public static void End(out Vector3 last)
    {
        Interlocked.Decrement(ref s_running);
        last = t_last;
        (t_sink, t_id, t_last) = (null, 0, default);
    }

    /// <summary>A sub-step decided, from <paramref name="from"/> to <paramref name="to"/> (world feet).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void SubStep(Vector3 from, Vector3 to)
    {
        if (On)
        {
            DrawSubStep(from, to);
        }
    }

    /// <summary>A contact at <paramref name="point"/> (world) with the wall of unit normal <paramref name="normal"/>.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)]
    public static void Contact(Vector3 point, Vector3 normal)
    {
        if (t_sink is IDebugSink sink)
        {
            sink.Line(point, point + (normal * PhysicsEngine.DrawNormalLength), DrawKind.Contact, t_id);
        }
    }

    /// <summary>
    /// A body's path stopped or turned by a wall: the contact on the body's side at the corner where it met it
    /// (<paramref name="centre"/>, world feet; <paramref name="normal"/> seen from above), half the body's height up.
    /// </summary>
    [MethodImpl(MethodImplOptions.NoInlining)]
    public static void BodyContact(Vector3 centre, Vector2 normal, MoverBody body)
    {
        var n = new Vector3(normal, 0f);
        Contact(centre - (n * body.Radius) + new Vector3(0f, 0f, 0.5f * body.Height), n);
    }

    /// <summary>A rise stopped under a surface at <paramref name="z"/> over <paramref name="feet"/> (world), whose unit normal is <paramref name="normal"/>.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Ceiling(Vector3 feet, float z, Vector3 normal)
    {
        if (On)
        {
            DrawCeiling(feet, z, normal);
        }
    }

    /// <summary>
    /// The edge a body was held at: its nearest point <paramref name="nearest"/> (landblock-local, as <paramref name="local"/>
    /// is the feet <paramref name="feet"/>, world), outward <paramref name="outward"/>, of the floor <paramref name="id"/>.
    /// </summary>
    [MethodImpl(MethodImplOptions.NoInlining)]
    public static void Edge(Vector3 feet, Vector2 local, Vector2 nearest, Vector2 outward, uint id)
    {
        if (t_sink is IDebugSink sink && outward != Vector2.Zero)
        {
            Vector3 at = feet + new Vector3(nearest - local, 0f);
            var along = new Vector3(-outward.Y, outward.X, 0f) * (0.5f * PhysicsEngine.DrawNormalLength);
            sink.Line(at - along, at + along, DrawKind.Edge, id);
        }
    }

    [MethodImpl(MethodImplOptions.NoInlining)]
    private static void DrawSubStep(Vector3 from, Vector3 to)
    {
        t_sink!.Line(from, to, DrawKind.SubStep, t_id);
        t_last = to;
    }

    [MethodImpl(MethodImplOptions.NoInlining)]
    private static void DrawCeiling(Vector3 feet, float z, Vector3 normal)
    {
        var at = new Vector3(feet.X, feet.Y, z);
        t_sink!.Line(at, at + (normal * PhysicsEngine.DrawNormalLength), DrawKind.Ceiling, t_id);
    }
}
