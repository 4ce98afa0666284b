namespace AcDream.Core.Physics;

/// <summary>
/// <c>PhysicsEngine.AddLandblock</c> refuses one of its objects: which one (its index in the list
/// given and its id) and the rule it breaks, so a caller can drop that object and register the rest.
/// The engine is unchanged.
/// </summary>
public sealed class ObjectRefusedException : ArgumentException
{
    /// <summary>An exception naming the object and rule; <paramref name="paramName"/> is the objects argument.</summary>
    internal ObjectRefusedException(string message, string paramName, int objectIndex, uint objectId, ObjectRule rule)
        : base(message, paramName)
    {
        ObjectIndex = objectIndex;
        ObjectId = objectId;
        Rule = rule;
    }

    /// <summary>The object's index in the list passed to <c>AddLandblock</c>.</summary>
    public int ObjectIndex { get; }

    /// <summary>The object's GfxObj or Setup id.</summary>
    public uint ObjectId { get; }

    /// <summary>The rule it breaks.</summary>
    public ObjectRule Rule { get; }
}
