using System.Numerics;
using AcDream.Core.Physics;

namespace AcDream.App.Capture;

/// <summary>The kinds of call a capture holds, one per <see cref="IEngineRecorder"/> method; the name in a line's <c>"kind"</c> is <see cref="CaptureJson.KindName"/>'s.</summary>
internal enum CaptureKind
{
    /// <summary><c>PhysicsEngine.AddLandblock</c>: <see cref="CaptureCall.Id"/> is the landblock.</summary>
    AddLandblock,

    /// <summary><c>PhysicsEngine.RemoveLandblock</c>: <see cref="CaptureCall.Id"/> is the landblock.</summary>
    RemoveLandblock,

    /// <summary><c>MoverRegistry.Add</c>.</summary>
    AddMover,

    /// <summary><c>MoverRegistry.Move</c>.</summary>
    MoveMover,

    /// <summary><c>MoverRegistry.SetState</c>.</summary>
    SetState,

    /// <summary><c>MoverRegistry.Open</c>.</summary>
    Open,

    /// <summary><c>MoverRegistry.Close</c>.</summary>
    Close,

    /// <summary><c>MoverRegistry.Remove</c>, answered whether it was registered.</summary>
    RemoveMover,

    /// <summary><c>MoverRegistry.RemoveLandblock</c>, answered how many were removed.</summary>
    RemoveMovers,

    /// <summary><c>MoverRegistry.Commit</c>, answered the commit's number.</summary>
    Commit,

    /// <summary><c>PhysicsEngine.Resolve(in MoveRequest, Span&lt;uint&gt;)</c>, answered the <see cref="MoveResult"/> and the ids written.</summary>
    Resolve,

    /// <summary><c>PhysicsEngine.Cast(in CastRequest)</c>, answered the <see cref="CastHit"/>.</summary>
    Cast,
}

/// <summary>A mover's shape as a capture names it: a cylinder by its size, or a door of the scene's world by its name.</summary>
/// <param name="Cylinder">The cylinder's radius and height (<see cref="MoverShape.Cylinder"/>), or null.</param>
/// <param name="Door">The name of the world's door (<c>HoltburgWorld.Doors</c>) whose shape it is, or null.</param>
internal sealed record CaptureShape(MoverBody? Cylinder, string? Door);

/// <summary>A capture's first line: the scene whose world the calls were made in, and the engine's frame.</summary>
/// <param name="Scene">"embedded default", or the scene file's path.</param>
/// <param name="Centre">The landblock the engine's frame is centred on (<c>0xXXYYFFFF</c>), or null for the global frame.</param>
internal sealed record CaptureHeader(string Scene, uint? Centre)
{
    /// <summary>The header's scene name for the embedded default scene.</summary>
    public const string EmbeddedDefault = "embedded default";
}

/// <summary>The answer of a call, as far as its kind has one: what a replay compares bit for bit.</summary>
/// <param name="Removed">A <see cref="CaptureKind.RemoveMover"/>'s answer.</param>
/// <param name="Count">A <see cref="CaptureKind.RemoveMovers"/>'s answer.</param>
/// <param name="Commit">A <see cref="CaptureKind.Commit"/>'s answer: the commit's number.</param>
/// <param name="Move">A <see cref="CaptureKind.Resolve"/>'s answer.</param>
/// <param name="Touched">With it, the ids the call wrote into the caller's span (the first <c>min(TouchedCount, span)</c>).</param>
/// <param name="Hit">A <see cref="CaptureKind.Cast"/>'s answer.</param>
internal sealed record CaptureAnswer(bool Removed = false, int Count = 0, long Commit = 0, MoveResult Move = default, uint[]? Touched = null, CastHit Hit = default);

/// <summary>One call of a capture: its kind, its inputs (the fields its kind uses) and its answer.</summary>
/// <param name="Kind">The call.</param>
internal sealed record CaptureCall(CaptureKind Kind)
{
    /// <summary>The landblock, mover or door the call names (<c>0xXXYYFFFF</c> for a landblock).</summary>
    public uint Id { get; init; }

    /// <summary>An <see cref="CaptureKind.AddMover"/>'s shape.</summary>
    public CaptureShape? Shape { get; init; }

    /// <summary>A mover's position, world metres.</summary>
    public Vector3 Position { get; init; }

    /// <summary>A mover's cell, <c>0xXXYYCCCC</c>.</summary>
    public uint CellId { get; init; }

    /// <summary>A mover's orientation, as given.</summary>
    public Quaternion Orientation { get; init; }

    /// <summary>A mover's state (<see cref="CaptureKind.AddMover"/>, <see cref="CaptureKind.SetState"/>).</summary>
    public MoverState State { get; init; }

    /// <summary>A <see cref="CaptureKind.Resolve"/>'s request.</summary>
    public MoveRequest Move { get; init; }

    /// <summary>A <see cref="CaptureKind.Resolve"/>'s span length: how many touched ids the caller had room for.</summary>
    public int Span { get; init; }

    /// <summary>A <see cref="CaptureKind.Cast"/>'s request.</summary>
    public CastRequest Cast { get; init; }

    /// <summary>The call's answer; null for a kind that has none (it returned).</summary>
    public CaptureAnswer? Answer { get; init; }
}
