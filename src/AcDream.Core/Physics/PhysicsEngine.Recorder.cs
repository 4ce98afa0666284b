namespace AcDream.Core.Physics;

/// <summary>The engine's recorder: the opt-in hook that sees every call changing the engine or asking it a move or a cast.</summary>
public sealed partial class PhysicsEngine
{
    private IEngineRecorder? _recorder;

    /// <summary>
    /// What sees every call that changes this engine or asks it a move or a cast, with its answer (<see cref="IEngineRecorder"/>);
    /// null (the default): none, and a call pays one null check for it.
    /// </summary>
    /// <remarks>
    /// Set it before the first call to capture a run whole: a capture starts with the calls made after it is set. Set it from
    /// the thread that changes the engine, while no other call is under way (a call under way may or may not be seen). The
    /// recorder changes no answer: every answer is bit for bit the same with and without one.
    /// </remarks>
    /// <value>Null by default.</value>
    public IEngineRecorder? Recorder
    {
        get => _recorder;
        set
        {
            _recorder = value;
            _movers.Recorder = value;
        }
    }
}
